// stylos_fuzz_seeds OUT: writes the fuzz corpus's own seeds, made by the project's writers so that they
// follow the formats as written today: small PLY (binary, ASCII, with normals, colours and a scalar), XYZ,
// OBJ, a small .poct built from them (with a colour layer), a project with assemblies, guides, a legend and
// a plate, the legend, a plate layout, and développée sidecars (cylinder, cone, revolution). One folder per
// harness under OUT (ply, xyz, obj, poct, project, legend, plate, sidecar). scripts/fuzz-corpus.sh adds the
// files of ../shared/data and the regression inputs.
#include "stylos/core/annotation/Legend.h"
#include "stylos/core/io/PlyWriter.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/plate/PlateSpec.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/unroll/Meridian.h"
#include "stylos/core/unroll/UnrollMap.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace {

using namespace stylos::core;
namespace fs = std::filesystem;

void require(bool ok, const std::string& what)
{
    if (!ok) {
        std::cerr << "stylos_fuzz_seeds: " << what << "\n";
        std::exit(1);
    }
}

void writeText(const fs::path& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    require(out.good(), "cannot write " + path.string());
}

/** A patch of a bumpy cylinder, @p n points with normals, colours and an intensity. */
io::PointBatch patch(std::size_t n)
{
    io::PointSchema schema{true, true, {"intensity"}};
    io::PointBatch b;
    b.reset(schema, n);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 0.05 * double(i), z = 0.01 * double(i % 17);
        const double r = 0.3 + 0.002 * std::sin(7 * a);
        b.positions.insert(b.positions.end(), {r * std::cos(a), r * std::sin(a), z});
        b.normals.insert(b.normals.end(), {float(std::cos(a)), float(std::sin(a)), 0.0f});
        b.colors.insert(b.colors.end(), {std::uint8_t(i), std::uint8_t(3 * i), std::uint8_t(200)});
        b.scalars[0].push_back(double(i % 11));
    }
    return b;
}

void writePly(const fs::path& path, const io::PointBatch& batch, io::PointSchema schema, io::PlyWriterOptions options)
{
    io::PointBatch b = batch;
    if (!schema.hasNormals) b.normals.clear();
    if (!schema.hasColors) b.colors.clear();
    if (schema.scalarNames.empty()) b.scalars.clear();
    auto writer = io::PlyWriter::create(path, schema, options);
    require(writer.ok(), "PlyWriter: " + (writer.ok() ? "" : writer.error().message));
    require(writer->write(b).ok() && writer->finish().ok(), "cannot write " + path.string());
}

void pointSeeds(const fs::path& out)
{
    const io::PointBatch b = patch(60);
    io::PlyWriterOptions binary;
    writePly(out / "ply" / "patch-normals-colours.ply", b, {true, true, {"intensity"}}, binary);
    io::PlyWriterOptions floats;
    floats.positionType = io::PlyScalarType::Float32;
    writePly(out / "ply" / "patch-float.ply", b, {false, false, {}}, floats);
    std::string ascii = "ply\nformat ascii 1.0\ncomment hand-made\nelement vertex 4\nproperty double x\n"
                        "property double y\nproperty double z\nproperty float nx\nproperty float ny\n"
                        "property float nz\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                        "0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n0 1 0 0 0 1 0 0 255\n1 1 0.5 0 0 1 9 9 9\n3 0 1 2\n";
    writeText(out / "ply" / "quad-ascii.ply", ascii);

    std::string xyz, obj = "# patch\n";
    for (std::size_t i = 0; i < b.size(); ++i) {
        char line[200];
        std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.4f %.4f %.4f\n", b.positions[3 * i], b.positions[3 * i + 1],
                      b.positions[3 * i + 2], b.normals[3 * i], b.normals[3 * i + 1], b.normals[3 * i + 2]);
        xyz += line;
        std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\nvn %.4f %.4f %.4f\n", b.positions[3 * i],
                      b.positions[3 * i + 1], b.positions[3 * i + 2], b.normals[3 * i], b.normals[3 * i + 1],
                      b.normals[3 * i + 2]);
        obj += line;
    }
    writeText(out / "xyz" / "patch-normals.xyz", xyz);
    writeText(out / "xyz" / "patch.pts", "3\n0 0 0 10 1 2 3\n1 0 0 20 4 5 6\n0 1 0 30 7 8 9\n");
    writeText(out / "obj" / "patch.obj", obj + "f 1 2 3\n");

    octree::BuildOptions build;
    build.depth = 4;
    build.threads = 1;
    const fs::path source = out / "ply" / "patch-normals-colours.ply";
    auto report = octree::buildOctreeFile(source, out / "poct" / "patch-depth4.poct", build);
    require(report.ok(), "build: " + (report.ok() ? "" : report.error().message));
    build.depth = 2;
    build.normalCode = octree::NormalCodeKind::Paper15;
    report = octree::buildOctreeFile(out / "ply" / "patch-float.ply", out / "poct" / "patch-depth2-paper15.poct", build);
    require(report.ok(), "build: " + (report.ok() ? "" : report.error().message));
}

void jsonSeeds(const fs::path& out)
{
    const annotation::Legend legend = annotation::Legend::defaults();
    writeText(out / "legend" / "defaults.json", legend.toJson().dump(1));

    plate::PlateSpec spec;
    spec.caption = "Drum 1, fragment 3";
    spec.landscape = true;
    plate::PanelSpec dev;
    dev.layer = annotation::AnnotationLayer::Material;
    dev.hatches = true;
    plate::PanelSpec front;
    front.view = plate::PanelView::Front;
    front.scale = 5;
    front.atMm = std::array<double, 2>{20.0, 30.0};
    spec.panels = {dev, front};
    writeText(out / "plate" / "two-panels.json", spec.toJson().dump(1));

    scene::Scene scene;
    scene::Assembly assembly;
    assembly.name = "Drum 1 reconstruction";
    assembly.pose = scene::Pose::translation({1.0, 2.0, 3.0});
    const auto assemblyId = scene.addAssembly(assembly);
    scene::Fragment drum;
    drum.name = "Drum 2";
    drum.octreePath = out / "poct" / "patch-depth4.poct";
    drum.guides.push_back({"axis", scene::GuideKind::Axis, {0, 0, 0}, {0, 0, 1}});
    drum.guides.push_back({"flute 1", scene::GuideKind::Groove, {0.3, 0, 0}, {0, 0, 1}});
    drum.importFrame = {io::UpAxis::PosY, io::LengthUnit::Millimetre, {100.0, 200.0, 0.0}};
    const auto drumId = scene.add(drum);
    scene::Fragment piece;
    piece.name = "Fragment 3";
    piece.octreePath = out / "poct" / "missing.poct";
    piece.sourcePath = out / "ply" / "patch-float.ply";
    piece.assembly = assemblyId;
    piece.annotationLayer = "material";
    piece.pose = scene::Pose::fromTranslationAngles({{0.1, 0.2, 0.3}, {0.01, 0.02, 0.03}});
    scene.add(piece);
    scene.findAssembly(assemblyId)->drum = drumId;
    scene.setPlate(spec);
    writeText(out / "project" / "two-fragments.stylos", scene::ProjectFile::toJson(scene, out / "project" / "p.stylos"));

    const unroll::Axis axis{Eigen::Vector3d(0.1, -0.2, 0.0), Eigen::Vector3d(0, 0, 1)};
    auto cylinder = unroll::Surface::cylinder(axis, 0.3);
    auto cone = unroll::Surface::cone(axis, 0.3, -0.05, 0.29);
    auto meridian = unroll::Meridian::create({{0.0, 0.3}, {0.2, 0.32}, {0.4, 0.29}}, 0.05);
    require(cylinder.ok() && cone.ok() && meridian.ok(), "surfaces");
    auto revolution = unroll::Surface::revolution(axis, meridian.value(), 0.3);
    require(revolution.ok(), "revolution");
    const Eigen::Vector3d e1 = unroll::defaultReferenceDir(axis.direction);
    int k = 0;
    for (const unroll::Surface& s : {cylinder.value(), cone.value(), revolution.value()}) {
        const unroll::UnrollMap map(s, e1, 0.25, 0.002, 943, 200, 0.4);
        writeText(out / "sidecar" / ("map" + std::to_string(k++) + ".png.json"), map.toJson().dump(1));
    }
}

} // namespace

int main(int argc, char** argv)
{
    require(argc == 2, "usage: stylos_fuzz_seeds OUT");
    const fs::path out = argv[1];
    for (const char* d : {"ply", "xyz", "obj", "poct", "project", "legend", "plate", "sidecar"})
        fs::create_directories(out / d);
    pointSeeds(out);
    jsonSeeds(out);
    return 0;
}
