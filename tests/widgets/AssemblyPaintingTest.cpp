// Painting on the développée of an assembly with synthesized mouse events: a generated drum with its axis guide and
// a generated fragment of its design docked at its true place, in an assembly of a SceneDocument; the assembly's
// développée made by AssemblyDeveloppeeJob (as Tools › Développée of the assembly does). A brush stroke across the
// fragment's edge onto the drum labels exactly the leaves (by their own pixels, computed here from the octrees and
// the pose) that lie on the stroke's pixels where their piece is the one shown — the drum's leaves hidden under the
// fragment keep their label —, as ONE undo step that undo and redo restore byte for byte in both fragments; the
// overlay shows the class at the painted pixels and follows a label change made elsewhere (as the 3D lasso does).
// A fragment moved against the drum, or taken out of the assembly, after the développée was made: the stroke is
// refused with a message and nothing is labelled.
#include "WidgetTestSupport.h"

#include "DeveloppeeLink.h"

#include "stylos/core/annotation/LabelRaster.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/annotation/PaintRegion.h"
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/octree/OctreeBuild.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/synth/SyntheticScan.h"
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/developpee/AssemblyDeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeePanel.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <map>
#include <set>

using namespace stylos;
using namespace stylos::widgets;
using core::annotation::AnnotationLayer;
using core::scene::FragmentId;

namespace {

constexpr std::uint64_t kDesign = 21;

struct Piece {
    std::filesystem::path poct;
    Eigen::Affine3d toOutput; ///< object (drum design) frame → file frame
};

/** A generated scan by one all-round station, built into a .poct with leaves of about 2.5 mm. */
Piece makePiece(const QString& dir, const std::string& name, core::synth::SyntheticKind kind, std::uint64_t seed)
{
    core::synth::SyntheticOptions o;
    o.spacing = 0.005;
    o.seed = seed;
    o.designSeed = kDesign;
    o.scans = 1;
    o.scanHalfAngle = std::numbers::pi;
    o.writeNormals = true;
    const std::filesystem::path folder(dir.toStdString());
    auto generated = core::synth::generateScan(kind, o, folder / (name + ".ply"));
    if (!generated) qFatal("generateScan: %s", generated.error().message.c_str());
    std::ifstream in(generated->truthPath);
    const auto truth = nlohmann::json::parse(in);
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i) m(i / 4, i % 4) = truth["stations"][0]["toOutput"][std::size_t(i)].get<double>();
    Piece piece{folder / (name + ".poct"), Eigen::Affine3d(m)};
    core::octree::BuildOptions build;
    build.depth = kind == core::synth::SyntheticKind::Drum ? 9 : 8;
    build.threads = 1;
    if (auto built = core::octree::buildOctreeFile(folder / (name + ".ply"), piece.poct, build); !built)
        qFatal("build: %s", built.error().message.c_str());
    return piece;
}

std::shared_ptr<const core::octree::PackedOctree> open(const Piece& piece)
{
    auto opened = core::octree::PackedOctree::open(piece.poct);
    if (!opened) qFatal("open: %s", opened.error().message.c_str());
    return std::make_shared<const core::octree::PackedOctree>(std::move(*opened));
}

void send(QWidget& w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent event(type, pos, w.mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(&w, &event);
}

} // namespace

class AssemblyPaintingTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void aStrokeAcrossTheFragmentAndTheDrumIsOneUndoStep();
    void theOverlayFollowsLabelsChangedElsewhere();
    void aStaleDeveloppeeRefusesToPaint();
    void theAssemblysRowShowsItsDeveloppeeAgain();

private:
    /** Drags the brush along row @p row from column @p from to column @p to; the pixels its dabs take. */
    std::set<std::uint32_t> stroke(int row, int from, int to);
    std::vector<std::uint8_t> labels(FragmentId id) const { return *m_document->labels().labels(id, AnnotationLayer::Material); }
    /** The leaves of piece @p id (0: the drum) whose pixel, by the octree and the pose, is in @p pixels and shows it. */
    std::set<std::uint32_t> expectedLeaves(std::uint64_t id, const std::set<std::uint32_t>& pixels) const;

    QTemporaryDir m_dir;
    Piece m_drumPiece, m_fragmentPiece;
    std::unique_ptr<TaskManager> m_tasks;
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<DeveloppeeView> m_view;
    std::unique_ptr<DeveloppeeAnnotator> m_annotator;
    FragmentId m_drum = 0, m_fragment = 0;
    core::scene::AssemblyId m_assembly = 0;
    DeveloppeeResult m_result;
    std::vector<std::int64_t> m_drumPixels, m_fragmentPixels; ///< per leaf, computed here
    int m_row = -1, m_edge = -1; ///< a row where the fragment's pixels end at column m_edge (drum pixels beyond)
};

void AssemblyPaintingTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_drumPiece = makePiece(m_dir.path(), "drum", core::synth::SyntheticKind::Drum, 101);
    m_fragmentPiece = makePiece(m_dir.path(), "fragment", core::synth::SyntheticKind::Fragment, 5);
}

void AssemblyPaintingTest::init()
{
    m_tasks = std::make_unique<TaskManager>();
    m_document = std::make_unique<SceneDocument>(*m_tasks);
    // The drum where its file puts it, with its axis guide (its design's axis in its file frame).
    core::scene::Fragment drum;
    drum.name = "drum";
    drum.octreePath = m_drumPiece.poct;
    const Eigen::Vector3d origin = m_drumPiece.toOutput * Eigen::Vector3d::Zero();
    const Eigen::Vector3d direction = m_drumPiece.toOutput.linear() * Eigen::Vector3d::UnitZ();
    drum.guides.push_back({"axis", core::scene::GuideKind::Axis, {origin.x(), origin.y(), origin.z()},
                           {direction.x(), direction.y(), direction.z()}});
    m_drum = m_document->addFragment(drum, open(m_drumPiece));
    // The fragment at its true place on the drum: its file frame → the drum's design frame → the drum's file frame.
    core::scene::Fragment fragment;
    fragment.name = "fragment";
    fragment.octreePath = m_fragmentPiece.poct;
    const Eigen::Affine3d toDrum = m_drumPiece.toOutput * m_fragmentPiece.toOutput.inverse();
    fragment.pose = core::scene::poseFromEigen(toDrum.matrix());
    m_fragment = m_document->addFragment(fragment, open(m_fragmentPiece));
    m_assembly = m_document->newAssembly(QStringLiteral("Drum 1"), {m_fragment});
    QVERIFY(m_assembly != core::scene::NoAssembly);
    QVERIFY(m_document->setAssemblyDrum(m_assembly, m_drum));
    QVERIFY(m_document->labels().labels(m_drum, AnnotationLayer::Material));
    QVERIFY(m_document->labels().labels(m_fragment, AnnotationLayer::Material));

    // The assembly's développée, as DeveloppeeLink::computeAssembly starts it.
    const Eigen::Isometry3d drumWorld(core::scene::toEigen(m_document->worldPose(m_drum)));
    const Eigen::Isometry3d fragmentWorld(core::scene::toEigen(m_document->worldPose(m_fragment)));
    DeveloppeeSettings settings;
    settings.shading = DeveloppeeShading::Height;
    settings.axis = core::unroll::Axis{origin, direction};
    const AssemblyDeveloppeeJob job(QString::fromStdString(m_drumPiece.poct.string()), m_drum,
                                    core::unroll::Axis{origin, direction},
                                    {{QString::fromStdString(m_fragmentPiece.poct.string()),
                                      drumWorld.inverse() * fragmentWorld, m_fragment}},
                                    settings, QStringLiteral("Drum 1"));
    auto made = job.run();
    QVERIFY2(made.ok(), made.ok() ? "" : made.error().message.c_str());
    m_result = *made;
    QVERIFY(m_result.assemblyIndex);
    QCOMPARE(m_result.assemblyIndex->pieces().size(), std::size_t(2));
    for (const auto& piece : m_result.assemblyIndex->pieces()) // for the record: what the index holds
        qInfo("piece %llu: %zu leaves, %zu on its shown pixels, window %d x %d", (unsigned long long)piece.id,
              piece.index.leafCount(), piece.index.mappedLeafCount(), piece.index.width(), piece.index.height());

    // Each leaf's pixel, computed here: the drum's by leafPixels (identity), the fragment's through the pose.
    const auto& map = *m_result.map;
    // Painting takes the surface the développée shows (core::annotation::paintDepth): the leaves under it or edge-on
    // to it are left out, on the drum and on the fragment alike.
    const double depth = core::annotation::paintDepth(map.pixelSize());
    m_drumPixels = core::annotation::leafPixels(*m_document->octree(m_drum), map, nullptr, depth).value();
    const Eigen::Isometry3d pose = drumWorld.inverse() * fragmentWorld;
    const auto& octree = *m_document->octree(m_fragment);
    m_fragmentPixels.assign(core::annotation::leafCount(octree), -1);
    octree.forEachCell(octree.depth(), [&](const core::octree::CellView& cell) {
        const auto hit = map.pixelOf(pose * Eigen::Vector3d(cell.centre[0], cell.centre[1], cell.centre[2]));
        if (hit && hit->column >= 0 && hit->row >= 0 && hit->column < map.width() && hit->row < map.height())
            m_fragmentPixels[cell.index] = std::int64_t(std::floor(hit->row)) * map.width() + std::int64_t(std::floor(hit->column));
        return true;
    });
    const auto shown = core::annotation::posedLeafPixels(octree, pose, map, nullptr, depth).value();
    std::size_t kept = 0;
    for (std::size_t l = 0; l < shown.size(); ++l) {
        if (shown[l] >= 0) QCOMPARE(shown[l], m_fragmentPixels[l]); // where shown, the same pixel as computed here
        else m_fragmentPixels[l] = -1;
        kept += shown[l] >= 0 ? 1 : 0;
    }
    QVERIFY(kept > 0);

    m_view = std::make_unique<DeveloppeeView>();
    m_view->resize(1200, 500);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    QVERIFY(m_view->setResult(m_result));
    QVERIFY(m_view->canPaint());
    m_annotator = std::make_unique<DeveloppeeAnnotator>(*m_document, *m_view);
    m_annotator->setActive(AnnotationLayer::Material, 1);
    m_view->setTool(PaintTool::Brush);
    m_view->setBrushSize(0.5 * map.pixelSize()); // one pixel wide

    // A row through the middle of the fragment: its right edge, with drum pixels (with heights) beyond it.
    const int w = map.width(), h = map.height();
    int bestLength = 0;
    for (int r = 0; r < h; ++r) {
        int first = -1, last = -1;
        for (int c = 0; c < w; ++c)
            if (m_view->pieceAt(c, r) == m_fragment) {
                if (first < 0) first = c;
                last = c;
            }
        if (first >= 0 && last + 12 < w && last - first > bestLength && m_result.heights->hasHeight(last + 10, r)) {
            bestLength = last - first;
            m_row = r;
            m_edge = last;
        }
    }
    QVERIFY2(m_row >= 0 && bestLength > 10, qPrintable(QString::number(bestLength)));
}

void AssemblyPaintingTest::cleanup()
{
    m_annotator.reset();
    m_view.reset();
    m_document.reset();
    m_tasks.reset();
}

std::set<std::uint32_t> AssemblyPaintingTest::stroke(int row, int from, int to)
{
    const QPointF a = m_view->imageToWidget(QPointF(from + 0.5, row + 0.5)), b = m_view->imageToWidget(QPointF(to + 0.5, row + 0.5));
    send(*m_view, QEvent::MouseButtonPress, a, Qt::LeftButton, Qt::LeftButton);
    send(*m_view, QEvent::MouseMove, b, Qt::NoButton, Qt::LeftButton);
    send(*m_view, QEvent::MouseButtonRelease, b, Qt::LeftButton, Qt::NoButton);
    // What the dabs take: the press's and the drag's (the brush's own rule, on the image positions reached).
    const double radius = std::max(0.5 * m_view->brushSize() / m_view->map()->pixelSize(), 0.7072);
    const auto ia = m_view->widgetToImage(a), ib = m_view->widgetToImage(b);
    const int w = m_view->image().width(), h = m_view->image().height();
    std::set<std::uint32_t> pixels;
    for (std::uint32_t p : core::annotation::brushPixels({ia.x(), ia.y()}, {ia.x(), ia.y()}, radius, w, h)) pixels.insert(p);
    for (std::uint32_t p : core::annotation::brushPixels({ia.x(), ia.y()}, {ib.x(), ib.y()}, radius, w, h)) pixels.insert(p);
    return pixels;
}

std::set<std::uint32_t> AssemblyPaintingTest::expectedLeaves(std::uint64_t id, const std::set<std::uint32_t>& pixels) const
{
    const auto& leafPixels = id == 0 ? m_drumPixels : m_fragmentPixels;
    const int w = m_view->image().width();
    std::set<std::uint32_t> out;
    for (std::size_t l = 0; l < leafPixels.size(); ++l) {
        const std::int64_t p = leafPixels[l];
        if (p >= 0 && pixels.count(std::uint32_t(p)) && m_view->pieceAt(int(p % w), int(p / w)) == (id == 0 ? 0 : m_fragment))
            out.insert(std::uint32_t(l));
    }
    return out;
}

void AssemblyPaintingTest::aStrokeAcrossTheFragmentAndTheDrumIsOneUndoStep()
{
    const auto drumBefore = labels(m_drum), fragmentBefore = labels(m_fragment);
    const int steps = m_document->undoStack()->count();
    const std::set<std::uint32_t> pixels = stroke(m_row, m_edge - 10, m_edge + 10);

    const std::set<std::uint32_t> drumLeaves = expectedLeaves(0, pixels), fragmentLeaves = expectedLeaves(m_fragment, pixels);
    QVERIFY2(drumLeaves.size() > 5 && fragmentLeaves.size() > 5,
             qPrintable(QStringLiteral("%1 drum, %2 fragment").arg(drumLeaves.size()).arg(fragmentLeaves.size())));
    // Drum leaves under the fragment's pixels of the stroke exist, and are not labelled (hidden).
    std::size_t hidden = 0;
    for (std::size_t l = 0; l < m_drumPixels.size(); ++l)
        if (m_drumPixels[l] >= 0 && pixels.count(std::uint32_t(m_drumPixels[l])) && !drumLeaves.count(std::uint32_t(l))) ++hidden;
    QVERIFY(hidden > 0);

    const auto drumAfter = labels(m_drum), fragmentAfter = labels(m_fragment);
    for (std::size_t l = 0; l < drumAfter.size(); ++l) QCOMPARE(drumAfter[l], drumLeaves.count(std::uint32_t(l)) ? std::uint8_t(1) : drumBefore[l]);
    for (std::size_t l = 0; l < fragmentAfter.size(); ++l)
        QCOMPARE(fragmentAfter[l], fragmentLeaves.count(std::uint32_t(l)) ? std::uint8_t(1) : fragmentBefore[l]);
    // The exact counts, from the index too.
    const std::vector<std::uint32_t> list(pixels.begin(), pixels.end());
    QCOMPARE(m_result.assemblyIndex->leavesOf(0, list).size(), drumLeaves.size());
    QCOMPARE(m_result.assemblyIndex->leavesOf(m_fragment, list).size(), fragmentLeaves.size());

    // One undo step for both; undo and redo byte for byte.
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    m_document->undoStack()->undo();
    QCOMPARE(labels(m_drum), drumBefore);
    QCOMPARE(labels(m_fragment), fragmentBefore);
    m_document->undoStack()->redo();
    QCOMPARE(labels(m_drum), drumAfter);
    QCOMPARE(labels(m_fragment), fragmentAfter);

    // The overlay: the class at each painted pixel where the shown piece has leaves, 0 elsewhere on the stroke.
    const int w = m_view->image().width();
    std::size_t shownFragment = 0, shownDrum = 0;
    for (std::uint32_t p : pixels) {
        const std::uint64_t piece = m_view->pieceAt(int(p % w), int(p / w));
        const auto* index = m_result.assemblyIndex->find(piece == m_fragment ? m_fragment : 0);
        QVERIFY(index);
        const bool hasLeaves = !m_result.assemblyIndex->leavesOf(index->id, std::vector<std::uint32_t>{p}).empty();
        QCOMPARE(m_view->overlay().idAt(int(p % w), int(p / w)), hasLeaves ? std::uint8_t(1) : std::uint8_t(0));
        if (hasLeaves) (piece == m_fragment ? shownFragment : shownDrum) += 1;
    }
    QVERIFY(shownFragment > 3 && shownDrum > 3);
    m_document->undoStack()->undo(); // and the overlay follows the undo
    for (std::uint32_t p : pixels) QCOMPARE(m_view->overlay().idAt(int(p % w), int(p / w)), std::uint8_t(0));
}

void AssemblyPaintingTest::theOverlayFollowsLabelsChangedElsewhere()
{
    // As the 3D lasso does: the document labels some fragment leaves; their pixels (where the fragment shows) follow.
    const auto& index = *m_result.assemblyIndex;
    const auto* piece = index.find(m_fragment);
    QVERIFY(piece && piece->index.mappedLeafCount() > 100);
    // All the leaves of the first 20 pixels the fragment shows, and one more leaf elsewhere (not a majority there).
    std::vector<std::uint32_t> shown;
    for (std::uint32_t p = 0; p < std::uint32_t(m_view->image().width() * m_view->image().height()) && shown.size() < 21; ++p)
        if (index.shownAt(p) == m_fragment && !index.leavesOf(m_fragment, std::vector<std::uint32_t>{p}).empty()) shown.push_back(p);
    QCOMPARE(shown.size(), std::size_t(21));
    std::vector<std::uint32_t> leaves = index.leavesOf(m_fragment, std::span(shown).first(20));
    leaves.push_back(index.leavesOf(m_fragment, std::vector<std::uint32_t>{shown[20]}).front());
    QVERIFY(m_document->setLabels(m_fragment, AnnotationLayer::Material, leaves, 3, CommandText([] { return QStringLiteral("lasso"); })));
    const std::vector<std::uint32_t> pixels = index.pixelsOf(m_fragment, leaves);
    QVERIFY(!pixels.empty());
    const int w = m_view->image().width();
    const auto fragmentLabels = labels(m_fragment);
    std::size_t own = 0, borrowers = 0;
    for (std::uint32_t p : pixels) {
        // The majority of the fragment's leaves there, or, for a pixel without leaves, at the pixel lending it them.
        const bool hasLeaves = !index.leavesOf(m_fragment, std::vector<std::uint32_t>{p}).empty();
        (hasLeaves ? own : borrowers) += 1;
        const std::int64_t shown = index.shownPixel(p);
        QVERIFY(shown >= 0 && (hasLeaves ? shown == p : std::uint32_t(shown) != p));
        std::map<std::uint8_t, int> counts;
        for (std::uint32_t l : index.leavesOf(m_fragment, std::vector<std::uint32_t>{std::uint32_t(shown)})) ++counts[fragmentLabels[l]];
        const auto best = std::max_element(counts.begin(), counts.end(), [](auto a, auto b) { return a.second < b.second; });
        QVERIFY(best != counts.end());
        QCOMPARE(m_view->overlay().idAt(int(p % w), int(p / w)), best->first);
    }
    QCOMPARE(own, std::size_t(21));
    QVERIFY2(borrowers > 0, "no pixel borrows leaves: the job did not hand the field's states to the index");
    for (std::size_t i = 0; i < 20; ++i) QCOMPARE(m_view->overlay().idAt(int(shown[i] % w), int(shown[i] / w)), std::uint8_t(3));
}

void AssemblyPaintingTest::aStaleDeveloppeeRefusesToPaint()
{
    QSignalSpy refused(m_annotator.get(), &DeveloppeeAnnotator::refused);
    QVERIFY(m_annotator->staleReason().isEmpty());
    const auto drumBefore = labels(m_drum), fragmentBefore = labels(m_fragment);
    const int steps = m_document->undoStack()->count();

    // Re-posed against the drum: 1 mm out.
    const core::scene::Pose moved = core::scene::Pose::translation({0.001, 0.0, 0.0}) * m_document->worldPose(m_fragment);
    QVERIFY(m_document->setFragmentWorldPose(m_fragment, moved));
    QVERIFY(m_annotator->staleReason().contains(QStringLiteral("“fragment” was moved")));
    stroke(m_row, m_edge - 10, m_edge + 10);
    QCOMPARE(refused.size(), 1); // once a stroke
    QVERIFY(refused.first().first().toString().contains(QStringLiteral("Compute it again")));
    QCOMPARE(labels(m_drum), drumBefore);
    QCOMPARE(labels(m_fragment), fragmentBefore);
    QCOMPARE(m_document->undoStack()->count(), steps + 1); // the move only

    // Put back (undo): paintable again. Then taken out of the assembly: refused.
    m_document->undoStack()->undo();
    QVERIFY(m_annotator->staleReason().isEmpty());
    QVERIFY(m_document->moveToAssembly({m_fragment}, core::scene::NoAssembly));
    QVERIFY(m_annotator->staleReason().contains(QStringLiteral("no longer in the assembly")));
    stroke(m_row, m_edge - 10, m_edge + 10);
    QCOMPARE(refused.size(), 2);
    QCOMPARE(labels(m_drum), drumBefore);
    QCOMPARE(labels(m_fragment), fragmentBefore);
}

void AssemblyPaintingTest::theAssemblysRowShowsItsDeveloppeeAgain()
{
    // The assembly's développée, kept as its drum's (as DeveloppeeLink::computeAssembly keeps it): a fragment's row
    // shows the fragment (none computed), the assembly's row the assembly's développée again, its pieces outlined.
    m_document->setDeveloppee(m_drum, std::make_shared<const DeveloppeeResult>(m_result));
    stylos::widgets::DeveloppeePanel panel;
    stylos::app::DeveloppeeLink link(*m_document, panel, nullptr);
    link.setFragment(m_fragment);
    QVERIFY(!panel.view()->hasDeveloppee());
    link.showAssembly(m_assembly);
    QVERIFY(panel.view()->hasDeveloppee());
    QCOMPARE(panel.view()->image().size(), QSize(m_result.map->width(), m_result.map->height()));
    QVERIFY(panel.view()->canPaint()); // its pieces' index came with it
    link.setFragment(m_fragment);
    QVERIFY(!panel.view()->hasDeveloppee());
    // Only an assembly's développée: the drum's own, kept instead, is not shown for the assembly's row.
    DeveloppeeResult own = m_result;
    own.pieceAt.reset();
    own.assemblyIndex.reset();
    m_document->setDeveloppee(m_drum, std::make_shared<const DeveloppeeResult>(own));
    link.showAssembly(m_assembly);
    QVERIFY(!panel.view()->hasDeveloppee());
}

STYLOS_WIDGET_TEST_MAIN(AssemblyPaintingTest)
#include "AssemblyPaintingTest.moc"
