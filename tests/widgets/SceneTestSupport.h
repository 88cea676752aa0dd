#pragma once
// Helpers for the scene document tests: small generated scans and packed octrees (a few thousand points,
// built in well under a second), and a directory listing for "no stray files" checks.
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/synth/SyntheticScan.h"

#include <QDir>
#include <QString>
#include <QStringList>

namespace stylos::test {

/** Generates a synthetic @p kind scan at @p spacing metres into @p dir/@p name (and its truth sidecar). */
inline QString generateScanFile(const QString& dir, const QString& name, core::synth::SyntheticKind kind,
                                double spacing, bool normals)
{
    core::synth::SyntheticOptions options;
    options.spacing = spacing;
    options.scans = 1;
    options.writeNormals = normals;
    const QString path = QDir(dir).absoluteFilePath(name);
    const auto report = core::synth::generateScan(kind, options, path.toStdString());
    if (!report) qFatal("cannot generate %s: %s", qPrintable(path), report.error().message.c_str());
    return path;
}

/** A small `.poct` (a fragment at 1 cm spacing, ~5 k points, depth 5) at @p dir/@p name. */
inline QString makeOctreeFile(const QString& dir, const QString& name)
{
    const QString scan = generateScanFile(dir, name + QStringLiteral(".ply"), core::synth::SyntheticKind::Fragment,
                                          0.01, true);
    const QString octree = QDir(dir).absoluteFilePath(name);
    core::octree::BuildOptions options;
    options.depth = 5;
    options.threads = 1;
    const auto built = core::octree::buildOctreeFile(scan.toStdString(), octree.toStdString(), options);
    if (!built) qFatal("cannot build %s: %s", qPrintable(octree), built.error().message.c_str());
    return octree;
}

/** Every file and folder ("name/") under @p dir, recursively, relative to it, sorted. */
inline QStringList filesUnder(const QString& dir)
{
    QStringList files;
    const QDir root(dir);
    for (const QFileInfo& info : root.entryInfoList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot | QDir::Hidden)) {
        if (info.isDir()) {
            files << info.fileName() + QLatin1Char('/');
            for (const QString& inner : filesUnder(info.absoluteFilePath()))
                files << info.fileName() + QLatin1Char('/') + inner;
        } else {
            files << info.fileName();
        }
    }
    files.sort();
    return files;
}

} // namespace stylos::test
