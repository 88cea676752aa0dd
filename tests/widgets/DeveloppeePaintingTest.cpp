// Painting the annotation on the développée with synthesized mouse events: a hand-made 40 × 20 développée whose
// pixel ↔ leaf index sends leaf l to pixel l mod 800 (so a pixel's leaves are known exactly), over a real
// fragment's labels in a SceneDocument. Brush, eraser, polygon (and Escape), magic wand across a height step,
// hole fill; each stroke one undo step holding exactly the leaves under the touched pixels; the overlay follows
// every change (and only its pixels); panning with the middle button while a tool is active paints nothing.
// Then the Legend widget: rename, recolour, hatch, add, delete a used class (its cells moved), each one undo
// step; and the per-class cells and areas measured in the background.
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "stylos/core/annotation/LabelArea.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/annotation/PaintRegion.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/widgets/annotation/ClassMeasures.h"
#include "stylos/widgets/annotation/DeveloppeeAnnotator.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/annotation/LegendText.h"
#include "stylos/widgets/annotation/LegendWidget.h"
#include "stylos/widgets/annotation/PaintToolBar.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>

#include <cmath>
#include <set>

using stylos::core::annotation::AnnotationLayer;
using stylos::core::annotation::GridPoint;
using stylos::core::annotation::Hatch;
using stylos::core::annotation::PixelLeafIndex;
using stylos::core::scene::Fragment;
using stylos::core::scene::FragmentId;
using stylos::core::shading::HeightField;
using stylos::core::unroll::Axis;
using stylos::core::unroll::Surface;
using stylos::core::unroll::UnrollMap;
using namespace stylos::widgets;

namespace {

constexpr int W = 40;
constexpr int H = 20;
constexpr int P = W * H;
constexpr double PixelSize = 0.01; // 10 mm pixels

void send(QWidget& w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent event(type, pos, w.mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(&w, &event);
}

void key(QWidget& w, int k)
{
    QKeyEvent press(QEvent::KeyPress, k, Qt::NoModifier);
    QApplication::sendEvent(&w, &press);
}

} // namespace

class DeveloppeePaintingTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void brushStrokeLabelsTheLeavesUnderItAsOneUndoStep();
    void eraserUnlabels();
    void polygonFillsItsInsideAndEscapeCancels();
    void magicWandStopsAtTheHeightStep();
    void holeFillTakesWhatTheRegionEncloses();
    void overlayFollowsEditsMadeElsewhere();
    void middleDragPansWithoutPainting();
    void toolBarSetsTheView();
    void legendEditsAreUndoSteps();
    void removingAUsedClassMovesItsCells();
    void measuresCountCellsAndAreas();

private:
    QPointF widgetAt(double column, double row) const { return m_view->imageToWidget(QPointF(column, row)); }
    std::vector<std::uint8_t> labels(AnnotationLayer layer = AnnotationLayer::Material) const
    {
        return *m_document->labels().labels(m_id, layer);
    }
    /** The labels expected when exactly @p pixels hold @p id (leaf l lies on pixel l mod P). */
    std::vector<std::uint8_t> expected(const std::set<std::uint32_t>& pixels, std::uint8_t id) const
    {
        std::vector<std::uint8_t> out(m_leaves, 0);
        for (std::size_t l = 0; l < m_leaves; ++l)
            if (pixels.count(std::uint32_t(l % P))) out[l] = id;
        return out;
    }

    QTemporaryDir m_dir;
    QString m_octreePath;
    SceneDocument::OctreePtr m_octree;
    std::size_t m_leaves = 0;
    std::shared_ptr<const PixelLeafIndex> m_index;
    std::shared_ptr<HeightField> m_heights;
    std::optional<UnrollMap> m_map;
    QImage m_image;

    std::unique_ptr<TaskManager> m_tasks;
    std::unique_ptr<SceneDocument> m_document;
    std::unique_ptr<DeveloppeeView> m_view;
    std::unique_ptr<DeveloppeeAnnotator> m_annotator;
    FragmentId m_id = 0;
};

void DeveloppeePaintingTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_octreePath = stylos::test::makeOctreeFile(m_dir.path(), QStringLiteral("piece.poct"));
    auto opened = stylos::core::octree::PackedOctree::open(m_octreePath.toStdString());
    QVERIFY(opened.ok());
    m_octree = std::make_shared<const stylos::core::octree::PackedOctree>(std::move(opened).value());
    m_leaves = stylos::core::annotation::leafCount(*m_octree);
    QVERIFY2(m_leaves >= P, qPrintable(QString::number(m_leaves))); // every pixel has a leaf
    std::vector<std::int64_t> leafPixels(m_leaves);
    for (std::size_t l = 0; l < m_leaves; ++l) leafPixels[l] = std::int64_t(l % P);
    m_index = std::make_shared<const PixelLeafIndex>(PixelLeafIndex::build(leafPixels, W, H));

    const Axis axis{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
    m_map.emplace(Surface::cylinder(axis, 0.5).value(), stylos::core::unroll::defaultReferenceDir(axis.direction), 0.0,
                  PixelSize, W, H, 0.2);
    // Heights: 0 left of column 20, a 5 mm step from column 20; pixel (3, 3) Empty. Grey image, opaque.
    m_heights = std::make_shared<HeightField>(HeightField::create(W, H, PixelSize).value());
    m_image = QImage(W, H, QImage::Format_ARGB32_Premultiplied);
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < W; ++c) {
            m_heights->setMeasured(c, r, c < 20 ? 0.0f : 0.005f);
            m_image.setPixel(c, r, c < 20 ? qRgb(100, 100, 100) : qRgb(200, 200, 200));
        }
    m_heights->clear(3, 3);
}

void DeveloppeePaintingTest::init()
{
    m_tasks = std::make_unique<TaskManager>();
    m_document = std::make_unique<SceneDocument>(*m_tasks);
    Fragment f;
    f.name = "piece";
    f.octreePath = m_octreePath.toStdString();
    m_id = m_document->addFragment(f, m_octree);
    m_document->undoStack()->clear();
    m_view = std::make_unique<DeveloppeeView>();
    m_view->resize(400, 300);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    m_annotator = std::make_unique<DeveloppeeAnnotator>(*m_document, *m_view);
    m_view->setDeveloppee(m_id, m_image, m_heights, *m_map, m_index);
    QVERIFY(m_view->canPaint());
    m_annotator->setActive(AnnotationLayer::Material, 2); // fractured marble
    QCOMPARE(m_view->activeClass(), std::uint8_t(2));
}

void DeveloppeePaintingTest::cleanup()
{
    m_annotator.reset();
    m_view.reset();
    m_document.reset();
    m_tasks.reset();
}

void DeveloppeePaintingTest::brushStrokeLabelsTheLeavesUnderItAsOneUndoStep()
{
    DeveloppeeView& v = *m_view;
    QVERIFY(!v.overlay().isEmpty());
    QCOMPARE(v.overlay().idAt(5, 5), std::uint8_t(0));
    key(v, Qt::Key_B);
    QCOMPARE(v.tool(), PaintTool::Brush);
    v.setBrushSize(0.03); // 30 mm: a radius of 1.5 pixels
    // A stroke from (5, 5) to (15, 8) in four moves; the expected pixels are the dabs' capsules.
    const std::vector<QPointF> path{widgetAt(5.0, 5.0), widgetAt(8.0, 5.5), widgetAt(11.0, 6.5), widgetAt(15.0, 8.0)};
    std::set<std::uint32_t> pixels;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const QPointF a = v.widgetToImage(path[i == 0 ? 0 : i - 1]), b = v.widgetToImage(path[i]);
        for (std::uint32_t p : stylos::core::annotation::brushPixels({a.x(), a.y()}, {b.x(), b.y()}, 1.5, W, H)) pixels.insert(p);
    }
    QVERIFY(pixels.size() > 30);
    QSignalSpy started(&v, &DeveloppeeView::strokeStarted);
    send(v, QEvent::MouseButtonPress, path[0], Qt::LeftButton, Qt::LeftButton);
    for (std::size_t i = 1; i < path.size(); ++i) send(v, QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(started.count(), 1);
    QCOMPARE(labels(), expected(pixels, 2));
    QCOMPARE(m_document->undoStack()->count(), 1); // one stroke, one step
    // The overlay: exactly those pixels, in the class's colour.
    const auto* cls = m_document->legend().find(AnnotationLayer::Material, 2);
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < W; ++c) {
            const bool painted = pixels.count(std::uint32_t(r * W + c)) > 0;
            QCOMPARE(v.overlay().idAt(c, r), std::uint8_t(painted ? 2 : 0));
            QCOMPARE(v.overlay().image().pixel(c, r), painted ? qRgb(cls->colour.r, cls->colour.g, cls->colour.b) : 0u);
        }
    m_document->undoStack()->undo();
    QCOMPARE(labels(), std::vector<std::uint8_t>(m_leaves, 0));
    QCOMPARE(v.overlay().idAt(5, 5), std::uint8_t(0));
    m_document->undoStack()->redo();
    QCOMPARE(labels(), expected(pixels, 2));
    QCOMPARE(v.overlay().idAt(5, 5), std::uint8_t(2));
}

void DeveloppeePaintingTest::eraserUnlabels()
{
    DeveloppeeView& v = *m_view;
    std::vector<std::uint32_t> all(m_leaves);
    for (std::size_t l = 0; l < m_leaves; ++l) all[l] = std::uint32_t(l);
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, all, 1, QStringLiteral("All")));
    v.setTool(PaintTool::Eraser);
    v.setBrushSize(0.01); // radius 0.5 pixel → the 0.7-pixel minimum: the pixel under the cursor only
    send(v, QEvent::MouseButtonPress, widgetAt(10.5, 10.5), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, widgetAt(10.5, 10.5), Qt::LeftButton, Qt::NoButton);
    std::vector<std::uint8_t> want(m_leaves, 1);
    for (std::size_t l = 0; l < m_leaves; ++l)
        if (l % P == std::size_t(10 * W + 10)) want[l] = 0;
    QCOMPARE(labels(), want);
    QCOMPARE(v.overlay().idAt(10, 10), std::uint8_t(0));
    QCOMPARE(v.overlay().idAt(11, 10), std::uint8_t(1));
    QCOMPARE(m_document->undoStack()->count(), 2);
}

void DeveloppeePaintingTest::polygonFillsItsInsideAndEscapeCancels()
{
    DeveloppeeView& v = *m_view;
    key(v, Qt::Key_L);
    QCOMPARE(v.tool(), PaintTool::Lasso);
    // A polygon started and cancelled: nothing.
    for (const QPointF& p : {widgetAt(1, 1), widgetAt(6, 1), widgetAt(6, 6)}) {
        send(v, QEvent::MouseButtonPress, p, Qt::LeftButton, Qt::LeftButton);
        send(v, QEvent::MouseButtonRelease, p, Qt::LeftButton, Qt::NoButton);
    }
    QCOMPARE(v.polygonInProgress().size(), std::size_t(3));
    key(v, Qt::Key_Escape);
    QVERIFY(v.polygonInProgress().empty());
    QCOMPARE(m_document->undoStack()->count(), 0);
    // A triangle closed with Enter.
    const std::vector<QPointF> corners{widgetAt(2, 2), widgetAt(12, 2), widgetAt(2, 12)};
    for (const QPointF& p : corners) {
        send(v, QEvent::MouseButtonPress, p, Qt::LeftButton, Qt::LeftButton);
        send(v, QEvent::MouseButtonRelease, p, Qt::LeftButton, Qt::NoButton);
    }
    key(v, Qt::Key_Return);
    std::vector<GridPoint> polygon;
    for (const QPointF& p : corners) polygon.push_back({v.widgetToImage(p).x(), v.widgetToImage(p).y()});
    const auto inside = stylos::core::annotation::polygonPixels(polygon, W, H);
    QVERIFY(inside.size() > 40);
    QCOMPARE(labels(), expected(std::set<std::uint32_t>(inside.begin(), inside.end()), 2));
    QCOMPARE(m_document->undoStack()->count(), 1);
}

void DeveloppeePaintingTest::magicWandStopsAtTheHeightStep()
{
    DeveloppeeView& v = *m_view;
    key(v, Qt::Key_W);
    v.setWandCriterion(WandCriterion::Height);
    v.setWandTolerance(0.001); // 1 mm: the 5 mm step stops it
    send(v, QEvent::MouseButtonPress, widgetAt(5.5, 10.5), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, widgetAt(5.5, 10.5), Qt::LeftButton, Qt::NoButton);
    std::set<std::uint32_t> left;
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < 20; ++c)
            if (!(c == 3 && r == 3)) left.insert(std::uint32_t(r * W + c)); // the Empty pixel stays out
    QCOMPARE(labels(), expected(left, 2));
    // On the shading, with a tolerance below the grey step (100 → 200 of 255): the right half.
    m_annotator->setActive(AnnotationLayer::Material, 3);
    v.setWandCriterion(WandCriterion::Shading);
    v.setWandTolerance(0.2);
    send(v, QEvent::MouseButtonPress, widgetAt(30.5, 2.5), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, widgetAt(30.5, 2.5), Qt::LeftButton, Qt::NoButton);
    auto want = expected(left, 2);
    for (std::size_t l = 0; l < m_leaves; ++l)
        if (int(l % P) % W >= 20) want[l] = 3;
    QCOMPARE(labels(), want);
    QCOMPARE(m_document->undoStack()->count(), 2);
}

void DeveloppeePaintingTest::holeFillTakesWhatTheRegionEncloses()
{
    DeveloppeeView& v = *m_view;
    // A ring of class 4 around columns 11..13, rows 6..8, with a class-1 pixel inside at (12, 7).
    std::vector<std::uint32_t> ring, island;
    for (std::size_t l = 0; l < m_leaves; ++l) {
        const int p = int(l % P), c = p % W, r = p / W;
        const bool box = c >= 10 && c <= 14 && r >= 5 && r <= 9;
        const bool inner = c >= 11 && c <= 13 && r >= 6 && r <= 8;
        if (box && !inner) ring.push_back(std::uint32_t(l));
        if (c == 12 && r == 7) island.push_back(std::uint32_t(l));
    }
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, ring, 4, QStringLiteral("Ring")));
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, island, 1, QStringLiteral("Island")));
    key(v, Qt::Key_H);
    QCOMPARE(v.tool(), PaintTool::Holes);
    send(v, QEvent::MouseButtonPress, widgetAt(10.5, 5.5), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, widgetAt(10.5, 5.5), Qt::LeftButton, Qt::NoButton);
    std::set<std::uint32_t> filled;
    for (int r = 5; r <= 9; ++r)
        for (int c = 10; c <= 14; ++c) filled.insert(std::uint32_t(r * W + c));
    QCOMPARE(labels(), expected(filled, 4)); // the hole, the island included, takes the ring's class
    QCOMPARE(m_document->undoStack()->count(), 3);
    // Clicking outside any region (unlabelled) does nothing.
    send(v, QEvent::MouseButtonPress, widgetAt(30.5, 15.5), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, widgetAt(30.5, 15.5), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(m_document->undoStack()->count(), 3);
}

void DeveloppeePaintingTest::overlayFollowsEditsMadeElsewhere()
{
    DeveloppeeView& v = *m_view;
    // Pixel (7, 2) holds leaves 87, 887, 1687, …: one of them class 3 is a minority; all of them make it 3.
    const std::uint32_t pixel = 2 * W + 7;
    std::vector<std::uint32_t> leaves;
    for (std::size_t l = pixel; l < m_leaves; l += P) leaves.push_back(std::uint32_t(l));
    const std::vector<std::uint32_t> first{leaves.front()};
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, first, 3, QStringLiteral("One")));
    QCOMPARE(v.overlay().idAt(7, 2), std::uint8_t(leaves.size() == 1 ? 3 : 0)); // the majority (a tie: the smaller id)
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, leaves, 3, QStringLiteral("All")));
    QCOMPARE(v.overlay().idAt(7, 2), std::uint8_t(3));
    // The tool-mark layer is another overlay: switching shows it (empty), and back.
    m_annotator->setActive(AnnotationLayer::Toolmark, 3);
    QCOMPARE(v.overlay().idAt(7, 2), std::uint8_t(0));
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, first, 1, QStringLiteral("Hidden layer")));
    QCOMPARE(v.overlay().idAt(7, 2), std::uint8_t(0));
    m_annotator->setActive(AnnotationLayer::Material, 1);
    QCOMPARE(v.overlay().idAt(7, 2), std::uint8_t(leaves.size() > 2 ? 3 : 1));
    // The opacity is the view's, the ids unchanged.
    v.setOverlayOpacity(0.25);
    QCOMPARE(v.overlayOpacity(), 0.25);
}

void DeveloppeePaintingTest::middleDragPansWithoutPainting()
{
    DeveloppeeView& v = *m_view;
    v.setTool(PaintTool::Brush);
    const QPointF offset = v.offset();
    send(v, QEvent::MouseButtonPress, QPointF(100, 100), Qt::MiddleButton, Qt::MiddleButton);
    send(v, QEvent::MouseMove, QPointF(140, 120), Qt::NoButton, Qt::MiddleButton);
    send(v, QEvent::MouseButtonRelease, QPointF(140, 120), Qt::MiddleButton, Qt::NoButton);
    QCOMPARE(v.offset(), offset + QPointF(40, 20));
    QCOMPARE(m_document->undoStack()->count(), 0);
    // A développée without an index cannot be painted: the press pans instead.
    v.setDeveloppee(m_id, m_image, m_heights, *m_map, nullptr);
    QVERIFY(!v.canPaint());
    QVERIFY(v.overlay().isEmpty());
    send(v, QEvent::MouseButtonPress, widgetAt(5, 5), Qt::LeftButton, Qt::LeftButton);
    send(v, QEvent::MouseButtonRelease, widgetAt(5, 5), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(m_document->undoStack()->count(), 0);
}

void DeveloppeePaintingTest::toolBarSetsTheView()
{
    PaintToolBar bar(*m_document, *m_annotator, *m_view);
    auto* size = bar.findChild<QDoubleSpinBox*>(QStringLiteral("paintBrushSize"));
    auto* layer = bar.findChild<QComboBox*>(QStringLiteral("paintLayer"));
    auto* cls = bar.findChild<QComboBox*>(QStringLiteral("paintClass"));
    QVERIFY(size && layer && cls);
    size->setValue(25.0);
    QCOMPARE(m_view->brushSize(), 0.025);
    // Typed: scientific notation is read; a value out of range is not applied (the plain box made 600 into 60).
    m_view->setTool(PaintTool::Brush); // the size is off for the tools without one
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QVERIFY(size->isEnabled());
    const auto type = [size](const QString& text) {
        size->setFocus();
        size->selectAll();
        QTest::keyClicks(size, text);
        QTest::keyClick(size, Qt::Key_Return);
    };
    type(QStringLiteral("1.5e1")); // the plain box read 1.51
    QCOMPARE(m_view->brushSize(), 0.015);
    type(QStringLiteral("600"));
    QCOMPARE(m_view->brushSize(), 0.015);
    size->setValue(25.0);
    QCOMPARE(cls->currentData().toInt(), 2);
    QCOMPARE(cls->count(), 4);
    layer->setCurrentIndex(layer->findData(int(AnnotationLayer::Toolmark)));
    QCOMPARE(m_annotator->layer(), AnnotationLayer::Toolmark);
    QCOMPARE(cls->count(), 5);
    QCOMPARE(cls->currentText(), QStringLiteral("point"));
    cls->setCurrentIndex(cls->findData(3));
    QCOMPARE(m_view->activeClass(), std::uint8_t(3));
    m_view->setTool(PaintTool::Wand);
    QVERIFY(bar.findChild<QAbstractButton*>(QStringLiteral("paintTool%1").arg(int(PaintTool::Wand)))->isChecked());
}

void DeveloppeePaintingTest::legendEditsAreUndoSteps()
{
    LegendWidget legend(*m_document, nullptr);
    QSignalSpy chosen(&legend, &LegendWidget::classChosen);
    QTreeWidgetItem* plaster = legend.itemOf(AnnotationLayer::Material, 3);
    QVERIFY(plaster);
    QCOMPARE(plaster->text(0), LegendText::className(AnnotationLayer::Material, *m_document->legend().find(AnnotationLayer::Material, 3)));
    legend.tree()->setCurrentItem(plaster);
    QCOMPARE(chosen.count(), 1);
    QCOMPARE(chosen.last().at(1).value<std::uint8_t>(), std::uint8_t(3));
    // Rename in place; the same shown text again is no step.
    plaster->setText(0, QStringLiteral("plâtre 1950"));
    QCOMPARE(m_document->legend().find(AnnotationLayer::Material, 3)->name, std::string("plâtre 1950"));
    QCOMPARE(m_document->undoStack()->count(), 1);
    QVERIFY(!legend.renameClass(AnnotationLayer::Material, 3, QStringLiteral("plâtre 1950")));
    QVERIFY(!legend.renameClass(AnnotationLayer::Material, 3, QStringLiteral("unknown"))); // taken by class 4
    // Recolour: the overlay's colours follow.
    std::vector<std::uint32_t> leaves; // every leaf of pixel (0, 0)
    for (std::size_t l = 0; l < m_leaves; l += P) leaves.push_back(std::uint32_t(l));
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, leaves, 3, QStringLiteral("Paint")));
    QCOMPARE(m_view->overlay().idAt(0, 0), std::uint8_t(3));
    QVERIFY(legend.setClassColour(AnnotationLayer::Material, 3, QColor(10, 20, 30)));
    QCOMPARE(m_view->overlay().image().pixel(0, 0), qRgb(10, 20, 30));
    // The hatch through its list.
    auto* hatch = legend.findChild<QComboBox*>(QStringLiteral("legendHatch_material_3"));
    QVERIFY(hatch);
    hatch->setCurrentIndex(hatch->findData(int(Hatch::Vertical)));
    QCOMPARE(m_document->legend().find(AnnotationLayer::Material, 3)->hatch, Hatch::Vertical);
    // Add: id 5, then undo every edit back to the defaults.
    QCOMPARE(legend.addClass(AnnotationLayer::Material), std::uint8_t(5));
    QVERIFY(legend.itemOf(AnnotationLayer::Material, 5));
    QCOMPARE(m_document->undoStack()->count(), 5);
    m_document->undoStack()->undo(); // add
    m_document->undoStack()->undo(); // hatch
    m_document->undoStack()->undo(); // colour
    m_document->undoStack()->undo(); // the paint
    m_document->undoStack()->undo(); // rename
    QCOMPARE(m_document->legend(), stylos::core::annotation::Legend::defaults());
    QVERIFY(!legend.itemOf(AnnotationLayer::Material, 5));
    QCOMPARE(legend.itemOf(AnnotationLayer::Material, 3)->text(0), QStringLiteral("plaster/restoration"));
}

void DeveloppeePaintingTest::removingAUsedClassMovesItsCells()
{
    LegendWidget legend(*m_document, nullptr);
    std::vector<std::uint32_t> leaves{1, 2, 3};
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Toolmark, leaves, 5, QStringLiteral("Rasp")));
    std::uint64_t asked = 0;
    legend.setRemovalChooser([&asked](AnnotationLayer, std::uint8_t, std::uint64_t cells) -> std::optional<std::uint8_t> {
        asked = cells;
        return std::nullopt; // cancel
    });
    QVERIFY(!legend.removeClass(AnnotationLayer::Toolmark, 5));
    QCOMPARE(asked, std::uint64_t(3));
    QVERIFY(m_document->legend().find(AnnotationLayer::Toolmark, 5));
    legend.setRemovalChooser([](AnnotationLayer, std::uint8_t, std::uint64_t) -> std::optional<std::uint8_t> { return 2; });
    QVERIFY(legend.removeClass(AnnotationLayer::Toolmark, 5));
    QVERIFY(!m_document->legend().find(AnnotationLayer::Toolmark, 5));
    QCOMPARE(labels(AnnotationLayer::Toolmark)[2], std::uint8_t(2));
    // An unused class goes without a question.
    asked = 0;
    legend.setRemovalChooser([&asked](AnnotationLayer, std::uint8_t, std::uint64_t c) -> std::optional<std::uint8_t> {
        asked = c + 1;
        return 0;
    });
    QVERIFY(legend.removeClass(AnnotationLayer::Toolmark, 4));
    QCOMPARE(asked, std::uint64_t(0));
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QCOMPARE(labels(AnnotationLayer::Toolmark)[2], std::uint8_t(5));
    QVERIFY(legend.itemOf(AnnotationLayer::Toolmark, 5));
}

void DeveloppeePaintingTest::measuresCountCellsAndAreas()
{
    ClassMeasures measures(*m_document);
    LegendWidget legend(*m_document, &measures);
    const auto areas = stylos::core::annotation::leafAreas(*m_octree).value();
    std::vector<std::uint32_t> leaves;
    double area = 0.0;
    for (std::uint32_t l = 0; l < m_leaves; l += 7) {
        leaves.push_back(l);
        area += areas[l];
    }
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, leaves, 2, QStringLiteral("Paint")));
    QTRY_VERIFY_WITH_TIMEOUT(!measures.isBusy() && measures.total(AnnotationLayer::Material, 2).cells > 0, 20000);
    QCOMPARE(measures.total(AnnotationLayer::Material, 2).cells, std::uint64_t(leaves.size()));
    QVERIFY(std::abs(measures.total(AnnotationLayer::Material, 2).areaM2 - area) < 1e-12);
    QCOMPARE(measures.total(AnnotationLayer::Material, 0).cells, std::uint64_t(m_leaves - leaves.size()));
    QCOMPARE(legend.itemOf(AnnotationLayer::Material, 2)->text(2), QLocale().toString(qulonglong(leaves.size())));
    // A second edit is measured again, with the cached leaf areas.
    const std::vector<std::uint32_t> more{1};
    QVERIFY(m_document->setLabels(m_id, AnnotationLayer::Material, more, 2, QStringLiteral("Paint")));
    QTRY_VERIFY_WITH_TIMEOUT(!measures.isBusy() && measures.total(AnnotationLayer::Material, 2).cells == leaves.size() + 1, 20000);
    QCOMPARE(measures.areaRuns(), 1);
    // Removing the fragment drops it from the sums.
    m_document->undoStack()->clear();
    QVERIFY(m_document->removeFragment(m_id));
    QCOMPARE(measures.total(AnnotationLayer::Material, 2).cells, std::uint64_t(0));
}

STYLOS_WIDGET_TEST_MAIN(DeveloppeePaintingTest)
#include "DeveloppeePaintingTest.moc"
