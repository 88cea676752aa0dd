// "Dock to flutes" in the workbench: a generated fragment placed ~2° about the drum axis and 5 mm radially off its
// true place against a generated drum of the same design (each a .poct added to a SceneDocument at a known pose)
// is docked by DockRunner in the background: the pose lands within 0.05° / 0.1 mm of the truth as exactly one undo
// step, and undo restores the start exactly; a second dock fits the drum's guides no more; a plain fragment (no
// flutes) reports why, moves nothing and leaves no undo step; the contact readout after the dock (ContactMonitor,
// ContactReadoutWidget) shows a largest interpenetration under 1.5 mm, and follows a pose that pushes it inside; in
// the window, Tools › Dock to flutes (Ctrl+J) is enabled only for another fragment than the docking drum and docks with
// the locks of Tools › Docking locks (θ and the tilts locked: the rotation stays exactly), the readout in Properties.
#include "DockGeometry.h"
#include "WidgetTestSupport.h"

#include "DeveloppeeLink.h"
#include "DockingActions.h"
#include "MainWindow.h"
#include "PropertiesDock.h"
#include "SceneDock.h"
#include "Translations.h"

#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/synth/SyntheticScan.h"
#include "stylos/widgets/docking/ContactMonitor.h"
#include "stylos/widgets/docking/ContactReadoutWidget.h"
#include "stylos/widgets/docking/DockRunner.h"
#include "stylos/widgets/docking/DrumGuidesCache.h"
#include "stylos/widgets/docking/GuideFitJob.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QAction>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>

using namespace stylos;
using widgets::ContactMonitor;
using widgets::DockRunner;
using widgets::DrumGuidesCache;
using widgets::SceneDocument;
using widgets::TaskManager;
namespace scene = core::scene;

namespace {

constexpr std::uint64_t kDesign = 21;
constexpr double kDegree = std::numbers::pi / 180.0;

/** A generated scan by one all-round station (its registration error is then a rigid motion known from the truth),
 *  built into a .poct with leaves of about 1 mm. */
struct Piece {
    std::filesystem::path poct;
    Eigen::Affine3d toOutput; ///< object frame → file frame
    Eigen::Vector3d centre;   ///< of the leaves, file frame
};

Piece makePiece(const QString& dir, const std::string& name, core::synth::SyntheticKind kind, std::uint64_t seed,
                int grooves, double spacing)
{
    core::synth::SyntheticOptions o;
    o.spacing = spacing;
    o.seed = seed;
    o.designSeed = kDesign;
    o.scans = 1;
    o.scanHalfAngle = std::numbers::pi;
    o.grooves = grooves;
    o.writeNormals = true;
    const std::filesystem::path folder(dir.toStdString());
    Piece piece;
    auto generated = core::synth::generateScan(kind, o, folder / (name + ".ply"));
    if (!generated) qFatal("generateScan: %s", generated.error().message.c_str());
    std::ifstream in(generated->truthPath);
    const auto truth = nlohmann::json::parse(in);
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = truth["stations"][0]["toOutput"][std::size_t(i)].get<double>();
    piece.toOutput = Eigen::Affine3d(m);
    auto cloud = core::cloud::loadPointCloud(folder / (name + ".ply"));
    if (!cloud) qFatal("load: %s", cloud.error().message.c_str());
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < cloud->size(); ++i) box.extend(cloud->world(i));
    core::octree::BuildOptions build;
    build.depth = std::clamp(int(std::ceil(std::log2(box.sizes().maxCoeff() / 0.0012))), 6, 12);
    build.threads = 1;
    piece.poct = folder / (name + ".poct");
    if (auto built = core::octree::buildOctreeFile(folder / (name + ".ply"), piece.poct, build); !built)
        qFatal("build: %s", built.error().message.c_str());
    auto leaves = core::cloud::loadPointCloud(piece.poct);
    if (!leaves) qFatal("load: %s", leaves.error().message.c_str());
    piece.centre = test::cloudCentre(*leaves);
    return piece;
}

Eigen::Isometry3d isometry(const scene::Pose& pose) { return Eigen::Isometry3d(scene::toEigen(pose)); }
scene::Pose poseOf(const Eigen::Isometry3d& m) { return scene::poseFromEigen(m.matrix()); }

} // namespace

class DockToFlutesTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void docksWithinTheTruthAsOneUndoStep();
    void aPlainFragmentMovesNothing();
    void theContactReadoutFollowsThePose();
    void theWindowDocksWithTheLocksChosen();
    void theFragmentUnrollsAtTheDrumsLeadingRadius();
    void theReadoutMeasuresTheOtherMembers();

private:
    /** A document holding the drum (with its fitted guides, the docking drum) at m_drumPose. */
    scene::FragmentId addDrum(SceneDocument& document) const;
    scene::FragmentId addPiece(SceneDocument& document, const Piece& piece, const std::string& name,
                               const Eigen::Isometry3d& pose) const;
    /** The piece's true pose in the drum file frame. */
    Eigen::Isometry3d truth(const Piece& piece) const
    {
        return Eigen::Isometry3d((m_drum.toOutput * piece.toOutput.inverse()).matrix());
    }
    /** The start: the truth turned by 2° about the drum axis and moved 5 mm out, in the scene. */
    Eigen::Isometry3d start(const Piece& piece) const
    {
        const Eigen::Isometry3d t = truth(piece);
        return m_drumPose * test::perturbed(t, m_frame, t * piece.centre, 2.0 * kDegree, 0.0, 0.005);
    }

    QTemporaryDir m_dir;
    Piece m_drum, m_fragment, m_plain;
    std::vector<scene::Guide> m_guides;
    core::dock::DrumFrame m_frame;
    Eigen::Isometry3d m_drumPose = Eigen::Isometry3d::Identity();
};

void DockToFlutesTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drum = makePiece(m_dir.path(), "drum", core::synth::SyntheticKind::Drum, 101, 48, 0.003);
    m_fragment = makePiece(m_dir.path(), "fragment", core::synth::SyntheticKind::Fragment, 5, 48, 0.003);
    m_plain = makePiece(m_dir.path(), "plain", core::synth::SyntheticKind::Fragment, 9, 0, 0.004);
    // The drum's guides as "Fit drum guides" gives them (the same job, run here).
    const widgets::GuideFitJob fit(QString::fromStdString(m_drum.poct.string()), 1);
    auto fitted = fit.run();
    QVERIFY2(fitted.ok(), fitted.ok() ? "" : fitted.error().message.c_str());
    QCOMPARE(fitted->flutes, 48);
    m_guides = fitted->guides;
    m_frame = core::dock::DrumFrame(*fitted->drum);
    m_drumPose = Eigen::Translation3d(0.4, -0.3, 0.2) * Eigen::AngleAxisd(30 * kDegree, Eigen::Vector3d(0.1, 0.2, 1).normalized());
}

scene::FragmentId DockToFlutesTest::addPiece(SceneDocument& document, const Piece& piece, const std::string& name,
                                             const Eigen::Isometry3d& pose) const
{
    scene::Fragment f;
    f.name = name;
    f.octreePath = piece.poct;
    f.pose = poseOf(pose);
    auto opened = core::octree::PackedOctree::open(piece.poct);
    if (!opened) qFatal("open: %s", opened.error().message.c_str());
    return document.addFragment(f, std::make_shared<const core::octree::PackedOctree>(std::move(*opened)));
}

scene::FragmentId DockToFlutesTest::addDrum(SceneDocument& document) const
{
    const scene::FragmentId drum = addPiece(document, m_drum, "drum", m_drumPose);
    document.setFragmentGuides(drum, m_guides);
    document.setDockingDrum(drum);
    return drum;
}

void DockToFlutesTest::docksWithinTheTruthAsOneUndoStep()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    DrumGuidesCache cache(document);
    DockRunner runner(document, cache);
    const scene::FragmentId drum = addDrum(document);
    const scene::Pose startPose = poseOf(start(m_fragment));
    const scene::FragmentId id = addPiece(document, m_fragment, "fragment", start(m_fragment));
    QVERIFY(!runner.canDock(drum)); // not the drum against itself
    QVERIFY(runner.canDock(id));
    QSignalSpy docked(&runner, &DockRunner::docked);
    QSignalSpy failed(&runner, &DockRunner::failed);
    const int steps = document.undoStack()->count();
    QVERIFY(runner.start(id));
    QVERIFY(!runner.start(id)); // one at a time
    QTRY_COMPARE_WITH_TIMEOUT(docked.size() + failed.size(), 1, 120000);
    QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().at(1).toString()));
    QCOMPARE(document.undoStack()->count(), steps + 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Dock fragment"));

    const Eigen::Isometry3d inDrum = m_drumPose.inverse() * isometry(document.fragment(id)->pose);
    const auto e = test::dockErrors(inDrum, truth(m_fragment), m_frame, m_fragment.centre);
    qInfo("errors: theta %.4f°, tilt %.4f°, radial %.4f mm, tangent %.4f mm, z %.4f mm", e.thetaDeg, e.tiltDeg,
          e.radialMm, e.tangentMm, e.zMm);
    QVERIFY2(e.thetaDeg < 0.05 && e.tiltDeg < 0.05, qPrintable(QString::number(e.thetaDeg) + " " + QString::number(e.tiltDeg)));
    QVERIFY2(e.radialMm < 0.1 && e.tangentMm < 0.1, qPrintable(QString::number(e.radialMm) + " " + QString::number(e.tangentMm)));
    const auto result = docked.first().at(1).value<widgets::DockJobResult>();
    QCOMPARE(result.dock.unobservable.size(), std::size_t(1));
    QCOMPARE(result.dock.unobservable.front(), core::dock::DockUnknown::Z);
    QVERIFY(std::abs(result.dock.fluteShift) > 0.2); // 2° is 0.27 of a flute pitch

    document.undoStack()->undo();
    QVERIFY(document.fragment(id)->pose == startPose); // exactly the start
    QCOMPARE(document.undoStack()->count(), steps + 1);

    // A second dock: the drum's guides come from the cache, not from a second fit.
    QCOMPARE(cache.fits(), 1);
    QVERIFY(runner.start(id));
    QTRY_COMPARE_WITH_TIMEOUT(docked.size(), 2, 120000);
    QCOMPARE(cache.fits(), 1);
    QCOMPARE(document.undoStack()->count(), steps + 1); // the redo branch replaced by the new dock
    tasks.cancelAllAndWait();
}

void DockToFlutesTest::aPlainFragmentMovesNothing()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    DrumGuidesCache cache(document);
    DockRunner runner(document, cache);
    addDrum(document);
    const Eigen::Isometry3d at = m_drumPose * truth(m_plain);
    const scene::FragmentId id = addPiece(document, m_plain, "plain", at);
    QSignalSpy docked(&runner, &DockRunner::docked);
    QSignalSpy failed(&runner, &DockRunner::failed);
    const int steps = document.undoStack()->count();
    QVERIFY(runner.start(id));
    QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 120000);
    QCOMPARE(docked.size(), 0);
    const QString message = failed.first().at(1).toString();
    QVERIFY2(message.startsWith(QStringLiteral("Could not dock plain:")), qPrintable(message));
    // Why, and what to do (DockJob::errorText from the core's DockFailure, in the user's language).
    QVERIFY2(message.contains(QStringLiteral("no flutes can be read on its outer face")) &&
                 message.contains(QStringLiteral("Lock θ (Tools › Docking locks)")),
             qPrintable(message));
    QVERIFY(document.fragment(id)->pose == poseOf(at));
    QCOMPARE(document.undoStack()->count(), steps);
    tasks.cancelAllAndWait();
}

void DockToFlutesTest::theContactReadoutFollowsThePose()
{
    TaskManager tasks;
    SceneDocument document(tasks);
    DrumGuidesCache cache(document);
    DockRunner runner(document, cache);
    ContactMonitor monitor(document, cache);
    monitor.setDelay(0);
    widgets::ContactReadoutWidget widget(monitor);
    addDrum(document);
    const scene::FragmentId id = addPiece(document, m_fragment, "fragment", start(m_fragment));
    monitor.setFragment(id);
    QTRY_COMPARE_WITH_TIMEOUT(monitor.state(), ContactMonitor::State::Ready, 120000);
    const double before = monitor.readout().medianGap; // 5 mm out, 2° off: the flutes do not meet
    const int atStart = monitor.deliveries();
    QSignalSpy docked(&runner, &DockRunner::docked);
    QVERIFY(runner.start(id));
    QTRY_COMPARE_WITH_TIMEOUT(docked.size(), 1, 120000);
    // The dock moved it: a new readout follows.
    QTRY_VERIFY_WITH_TIMEOUT(monitor.deliveries() > atStart && monitor.state() == ContactMonitor::State::Ready, 60000);
    const auto r = monitor.readout();
    qInfo("contact: %zu points, largest %.3f mm, median %.3f mm (before: %.3f mm), 90 %% %.3f mm, 99 %% %.3f mm, within %.3f",
          r.points, r.largestInterpenetration * 1e3, r.medianGap * 1e3, before * 1e3, r.gap90 * 1e3, r.gap99 * 1e3,
          r.withinHalfMillimetre);
    QVERIFY(r.points > 1000);
    QVERIFY2(r.largestInterpenetration < 0.0015, qPrintable(QString::number(r.largestInterpenetration)));
    QVERIFY(std::abs(r.medianGap) < 0.0003);
    QVERIFY(r.withinHalfMillimetre > 0.5);
    QCOMPARE(widget.interpenetrationLabel()->text(), QStringLiteral("%1 mm").arg(r.largestInterpenetration * 1e3, 0, 'f', 2));
    QVERIFY(widget.withinLabel()->text().endsWith(QStringLiteral(" %")));
    QCOMPARE(cache.fits(), 1); // the readout and the dock share the drum's guides

    // Pushed 3 mm into the drum: the readout follows; the older one is not shown again.
    const Eigen::Isometry3d now = isometry(document.fragment(id)->pose);
    const Eigen::Isometry3d inDrum = m_drumPose.inverse() * now;
    const int deliveries = monitor.deliveries();
    QVERIFY(document.setFragmentPose(id, poseOf(m_drumPose * test::perturbed(inDrum, m_frame, inDrum * m_fragment.centre,
                                                                                0.0, 0.0, -0.003))));
    QCOMPARE(monitor.state(), ContactMonitor::State::Computing);
    QTRY_COMPARE_WITH_TIMEOUT(monitor.state(), ContactMonitor::State::Ready, 60000);
    QCOMPARE(monitor.deliveries(), deliveries + 1);
    QVERIFY2(monitor.readout().largestInterpenetration > 0.003, qPrintable(QString::number(monitor.readout().largestInterpenetration)));
    QVERIFY(monitor.readout().medianGap < -0.0025);

    // No docking drum: nothing to show.
    document.setDockingDrum(scene::NoFragment);
    QCOMPARE(monitor.state(), ContactMonitor::State::Off);
    QCOMPARE(widget.interpenetrationLabel()->text(), QStringLiteral("—"));
    tasks.cancelAllAndWait();
}

void DockToFlutesTest::theWindowDocksWithTheLocksChosen()
{
    QSettings().clear();
    app::Translations translations;
    app::MainWindow window(translations, m_dir.filePath(QStringLiteral("demo")));
    window.setErrorDialogsEnabled(false);
    app::DockingActions& docking = window.docking();
    QAction* dock = docking.dockToFlutesAction();
    QCOMPARE(dock->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_J));
    QVERIFY(window.propertiesDock().contactReadout() != nullptr);

    SceneDocument& document = window.document();
    const scene::FragmentId drum = addPiece(document, m_drum, "drum", m_drumPose);
    document.setFragmentGuides(drum, m_guides);
    const Eigen::Isometry3d startPose = start(m_fragment);
    const scene::FragmentId id = addPiece(document, m_fragment, "fragment", startPose);
    window.sceneDock().selectFragment(id);
    QVERIFY(!dock->isEnabled()); // no docking drum yet
    document.setDockingDrum(drum);
    QVERIFY(dock->isEnabled());
    window.sceneDock().selectFragment(drum);
    QVERIFY(!dock->isEnabled()); // not the drum against itself
    window.sceneDock().selectFragment(id);
    QVERIFY(dock->isEnabled());

    QCOMPARE(docking.lockActions().size(), 4); // z, r, θ, tilts
    docking.lockActions()[2]->setChecked(true);
    docking.lockActions()[3]->setChecked(true);
    QVERIFY(docking.docker().isLocked(core::dock::DockUnknown::Theta));
    QVERIFY(docking.docker().isLocked(core::dock::DockUnknown::Tangent)); // the place round the drum
    QVERIFY(docking.docker().isLocked(core::dock::DockUnknown::TiltRoll));
    QVERIFY(!docking.docker().isLocked(core::dock::DockUnknown::R));
    const int steps = document.undoStack()->count();
    dock->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(document.undoStack()->count(), steps + 1, 120000);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Dock fragment"));
    const Eigen::Isometry3d docked = isometry(document.fragment(id)->pose);
    QVERIFY(docked.linear().isApprox(startPose.linear(), 1e-12)); // θ and the tilts locked: the rotation stays
    const Eigen::Isometry3d t = truth(m_fragment);
    const Eigen::Vector3d c = m_frame.toFrame(t * m_fragment.centre), m = m_frame.toFrame(m_drumPose.inverse() * docked * m_fragment.centre);
    // r is free: the fragment's centre is back on its radius (within what the locked 2° leave).
    QVERIFY2(std::abs(std::hypot(m.x(), m.y()) - std::hypot(c.x(), c.y())) < 0.001,
             qPrintable(QString::number(std::hypot(m.x(), m.y()) - std::hypot(c.x(), c.y()))));

    auto* readout = window.propertiesDock().contactReadout();
    QTRY_VERIFY_WITH_TIMEOUT(docking.contact().state() == ContactMonitor::State::Ready &&
                                 readout->interpenetrationLabel()->text() != QStringLiteral("—"), 60000);
    QVERIFY(readout->pointsLabel()->text() != QStringLiteral("—"));
    window.tasks().cancelAllAndWait();
    QSettings().clear();
}

void DockToFlutesTest::theFragmentUnrollsAtTheDrumsLeadingRadius()
{
    // The fragment (no axis of its own) at its true place against the drum: Compute in the Développée dock unrolls
    // it about the drum's axis at the drum guides' leading radius (fitted once, in the background, first), and the
    // drum's own développée at the same radius: the same millimetres per degree.
    TaskManager tasks;
    SceneDocument document(tasks);
    DrumGuidesCache cache(document);
    widgets::DeveloppeePanel panel;
    app::DeveloppeeLink link(document, panel, nullptr);
    link.setGuidesCache(&cache);
    const scene::FragmentId drum = addDrum(document);
    const scene::FragmentId id = addPiece(document, m_fragment, "fragment", m_drumPose * truth(m_fragment));
    link.setFragment(id);
    QVERIFY(panel.axisGuide().has_value()); // the drum's, carried into the fragment's frame
    link.compute();
    QTRY_VERIFY_WITH_TIMEOUT(document.developpee(id) != nullptr, 120000);
    const auto guides = cache.guides(drum);
    QVERIFY(guides != nullptr);
    const auto& fragmentSurface = document.developpee(id)->fit.surface;
    qInfo("leading radius %.3f mm; the fragment unrolled at %.3f mm", guides->radius * 1e3,
          fragmentSurface.referenceRadius() * 1e3);
    QCOMPARE(fragmentSurface.radius(), guides->radius);
    QCOMPARE(fragmentSurface.referenceRadius(), guides->radius);

    link.setFragment(drum);
    link.compute();
    QTRY_VERIFY_WITH_TIMEOUT(document.developpee(drum) != nullptr, 120000);
    QCOMPARE(document.developpee(drum)->fit.surface.referenceRadius(), guides->radius);
    QCOMPARE(cache.fits(), 1);
    tasks.cancelAllAndWait();
}

void DockToFlutesTest::theReadoutMeasuresTheOtherMembers()
{
    // The drum, the fragment at its true place and a copy of it 2 mm further in, in one assembly: the fragment's
    // readout lists the copy, about 2 mm into it (its inner face lies 2 mm inside the copy's), and follows the
    // copy's move out of reach.
    TaskManager tasks;
    SceneDocument document(tasks);
    DrumGuidesCache cache(document);
    ContactMonitor monitor(document, cache);
    monitor.setDelay(0);
    widgets::ContactReadoutWidget widget(monitor);
    const scene::FragmentId drum = addDrum(document);
    const Eigen::Isometry3d place = truth(m_fragment);
    const scene::FragmentId id = addPiece(document, m_fragment, "fragment", m_drumPose * place);
    const Eigen::Isometry3d inward = test::perturbed(place, m_frame, place * m_fragment.centre, 0.0, 0.0, -0.002);
    const scene::FragmentId copy = addPiece(document, m_fragment, "copy", m_drumPose * inward);
    const auto assembly = document.newAssembly(QStringLiteral("Drum 1"), {drum, id, copy});
    QVERIFY(assembly != scene::NoAssembly);
    QVERIFY(document.setAssemblyDrum(assembly, drum));
    monitor.setFragment(id);
    QTRY_COMPARE_WITH_TIMEOUT(monitor.state(), ContactMonitor::State::Ready, 120000);
    QCOMPARE(monitor.members().size(), std::size_t(1));
    const auto& member = monitor.members()[0];
    QCOMPARE(member.id, quint64(copy));
    qInfo("against the copy 2 mm in: %zu points, largest %.3f mm, median %.3f mm", member.readout.points,
          member.readout.largestInterpenetration * 1e3, member.readout.medianGap * 1e3);
    QVERIFY(member.readout.points > 100);
    QVERIFY2(std::abs(member.readout.largestInterpenetration - 0.002) < 0.0005,
             qPrintable(QString::number(member.readout.largestInterpenetration)));
    QVERIFY(widget.membersLabel()->text().contains(QStringLiteral("copy")));
    // The copy moved 1 m away sideways (along the axis it would still overlap: the piece is taller than 10 cm):
    // no contact with it any more.
    const int deliveries = monitor.deliveries();
    QVERIFY(document.setFragmentWorldPose(copy, poseOf(Eigen::Translation3d(1.0, 0.0, 0.0) * m_drumPose * inward)));
    QTRY_VERIFY_WITH_TIMEOUT(monitor.deliveries() > deliveries && monitor.state() == ContactMonitor::State::Ready, 60000);
    QCOMPARE(monitor.members()[0].readout.points, std::size_t(0));
    QVERIFY(widget.membersLabel()->text().contains(QStringLiteral("no contact")));
    tasks.cancelAllAndWait();
}

STYLOS_WIDGET_TEST_MAIN(DockToFlutesTest)
#include "DockToFlutesTest.moc"
