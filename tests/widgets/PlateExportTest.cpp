// File › Export plate… on a generated drum in a document: the dialog's preview is the real plate (drawn, Export
// enabled) and a scale that does not fit says which would (Export disabled); the dialog states back what it was
// given; the plate drawn as a task reads the document's unsaved labels; the plate kept in the project is one undo
// step and comes back from the saved project file; exporting a développée with none on show is refused; a view
// image is the chosen width along the 3D view's camera (none: refused).
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "PlateActions.h"
#include "stylos/core/annotation/LeafLabels.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/scene/ProjectFile.h"
#include "stylos/core/scene/SceneEigen.h"
#include "stylos/core/view/Camera.h"
#include "stylos/plate/PlateComposer.h"
#include "stylos/widgets/annotation/LabelStore.h"
#include "stylos/widgets/developpee/DeveloppeeJob.h"
#include "stylos/widgets/developpee/DeveloppeeView.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/plate/PlateDialog.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QDialogButtonBox>

#include <algorithm>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace stylos;
namespace cp = core::plate;
using core::annotation::AnnotationLayer;

/** A document and the plate actions of a window over it, as the workbench wires them. */
struct PlateBench {
    widgets::TaskManager tasks;
    widgets::SceneDocument document{tasks};
    QWidget window;
    widgets::DeveloppeeView view;
    app::PlateActions actions{document, view, window};
};

class PlateExportTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void previewDrawsAndRefusesWhatDoesNotFit();
    void anErrorThatIsNotTheLayoutsIsSaidAsItIs();
    void exportDrawsUnsavedLabelsAndKeepsThePlate();
    void viewImageIsTheChosenWidthAlongTheCamera();
    void aCancelledExportIsNoError();
    void theDefaultPlateFitsItsPage();
    void theDefaultPlateShowsTheCurrentFragmentAndItsPaint();
    void aPlateUnrollsAsTheDockDoes();

private:
    /** Adds the drum's octree (@p octree: another copy of it) as fragment @p name. */
    core::scene::FragmentId addDrum(widgets::SceneDocument& document, const std::string& name = "Drum 2",
                                    const QString& octree = {}) const;
    static cp::PlateSpec spec(double scale)
    {
        cp::PlateSpec s;
        s.landscape = true;
        s.dpi = 150;
        s.caption = "Drum, développée";
        cp::PanelSpec p;
        p.scale = scale;
        p.layer = AnnotationLayer::Material;
        s.panels = {p};
        return s;
    }

    QTemporaryDir m_dir;
    QString m_octree;
    QString m_unpainted; ///< a copy of m_octree that no test saves labels into
};

void PlateExportTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString scan = test::generateScanFile(m_dir.path(), QStringLiteral("drum.ply"), core::synth::SyntheticKind::Drum, 0.01, true);
    m_octree = QDir(m_dir.path()).absoluteFilePath(QStringLiteral("drum.poct"));
    core::octree::BuildOptions options;
    options.depth = 8;
    options.threads = 1;
    QVERIFY(core::octree::buildOctreeFile(scan.toStdString(), m_octree.toStdString(), options).ok());
    m_unpainted = QDir(m_dir.path()).absoluteFilePath(QStringLiteral("unpainted.poct"));
    QVERIFY(QFile::copy(m_octree, m_unpainted));
}

core::scene::FragmentId PlateExportTest::addDrum(widgets::SceneDocument& document, const std::string& name,
                                                 const QString& octree) const
{
    const QString path = octree.isEmpty() ? m_octree : octree;
    auto opened = core::octree::PackedOctree::open(path.toStdString());
    if (!opened) return 0;
    core::scene::Fragment f;
    f.name = name;
    f.octreePath = path.toStdString();
    return document.addFragment(f, std::make_shared<const core::octree::PackedOctree>(std::move(opened).value()));
}

void PlateExportTest::previewDrawsAndRefusesWhatDoesNotFit()
{
    widgets::TaskManager tasks;
    widgets::SceneDocument document(tasks);
    QVERIFY(addDrum(document) != 0);
    widgets::PlateDialog dialog(app::PlateActions::sourcesOf(document), spec(20));
    // Within the screen (1280 wide here, as a field laptop): its buttons never off it.
    QVERIFY2(dialog.width() <= dialog.screen()->availableGeometry().width(), qPrintable(QString::number(dialog.width())));
    QVERIFY(dialog.height() <= dialog.screen()->availableGeometry().height());
    // Two panels fit the panel table across: no sideways scrolling (the fragment's long "(all visible; …)" item made
    // the table scroll and hid the View column).
    {
        widgets::PlateDialog two(app::PlateActions::sourcesOf(document), spec(20));
        cp::PlateSpec both = spec(20);
        both.panels.push_back(both.panels[0]);
        both.panels[1].view = cp::PanelView::Front;
        both.panels[1].shading = cp::PanelShading::Headlight;
        two.setSpec(both);
        two.show();
        QVERIFY(QTest::qWaitForWindowExposed(&two));
        QApplication::processEvents();
        QCOMPARE(two.panelTable()->rowCount(), 2);
        QCOMPARE(two.panelTable()->horizontalScrollBar()->maximum(), 0);
    }
    QSignalSpy updated(&dialog, &widgets::PlateDialog::previewUpdated);
    QVERIFY(updated.wait(60000));
    QVERIFY2(dialog.messageLabel()->text().isEmpty(), qPrintable(dialog.messageLabel()->text()));
    QVERIFY(!dialog.previewImage().isNull());
    QVERIFY(dialog.previewImage().width() > dialog.previewImage().height()); // landscape
    QVERIFY(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    QCOMPARE(dialog.spec(), spec(20));

    auto* scale = qobject_cast<QDoubleSpinBox*>(dialog.panelTable()->cellWidget(0, 1));
    QVERIFY(scale);
    // Typed in scientific notation, 1:1000 (the plain spin box dropped the "e": 1:13).
    scale->selectAll();
    QTest::keyClicks(scale, QStringLiteral("1e3"));
    scale->interpretText();
    QCOMPARE(scale->value(), 1000.0);
    QCOMPARE(dialog.spec().panels[0].scale, 1000.0);
    scale->setValue(2);
    QVERIFY(!dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    QVERIFY(updated.wait(60000));
    // Worded by the dialog (the layout's values), not the layout's English: "The panel (Développée, 1:2) is …".
    QVERIFY2(dialog.messageLabel()->text().startsWith(QStringLiteral("The panel (Développée, 1:2) is ")) &&
                 dialog.messageLabel()->text().contains(QStringLiteral("use 1:")),
             qPrintable(dialog.messageLabel()->text()));
    QVERIFY(!dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    QVERIFY(dialog.previewImage().isNull()); // not the last page that fitted

    // A journal's print area: no margin, and the box turns the page as stated.
    auto* page = dialog.findChild<QComboBox*>(QStringLiteral("platePage"));
    auto* turned = dialog.findChild<QCheckBox*>(QStringLiteral("plateTurned"));
    auto* margin = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("plateMargin"));
    QVERIFY(page && turned && margin);
    margin->setValue(12);
    QCOMPARE(turned->text(), QStringLiteral("Landscape"));
    page->setCurrentIndex(page->findData(QStringLiteral("170x105")));
    QCOMPARE(margin->value(), 0.0);
    QCOMPARE(turned->text(), QStringLiteral("Turned (105 × 170 mm)"));
    QCOMPARE(dialog.spec().marginMm, 0.0);
    page->setCurrentIndex(page->findData(QStringLiteral("A3"))); // paper again: its margin back
    QCOMPARE(margin->value(), 12.0);
    QCOMPARE(turned->text(), QStringLiteral("Landscape"));
    // A page named in any case is the list's page, not one more entry.
    const int pages = page->count();
    core::plate::PlateSpec lower = dialog.spec();
    lower.pageName = "a4";
    dialog.setSpec(lower);
    QCOMPARE(page->count(), pages);
    QCOMPARE(page->currentData().toString(), QStringLiteral("A4"));
}

// A plate that fails for another reason than its page (here its fragment is missing) says that reason, not a
// "does not fit" with zero sizes (the layout's values were read whatever the error).
void PlateExportTest::anErrorThatIsNotTheLayoutsIsSaidAsItIs()
{
    widgets::TaskManager tasks;
    widgets::SceneDocument document(tasks);
    QVERIFY(addDrum(document) != 0);
    auto sources = std::make_shared<cp::PlateSources>(*app::PlateActions::sourcesOf(document));
    sources->fragments[0].missing = true;
    widgets::PlateDialog dialog(sources, spec(20));
    QSignalSpy updated(&dialog, &widgets::PlateDialog::previewUpdated);
    QVERIFY(updated.wait(60000));
    const QString message = dialog.messageLabel()->text();
    QVERIFY2(message.contains(QStringLiteral("is missing")) && !message.contains(QStringLiteral("print area")),
             qPrintable(message));
    QVERIFY(!dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
}

void PlateExportTest::exportDrawsUnsavedLabelsAndKeepsThePlate()
{
    PlateBench bench;
    widgets::SceneDocument& document = bench.document;
    const auto id = addDrum(document);
    QVERIFY(id != 0);
    const auto held = document.labels().labels(id, AnnotationLayer::Material);
    QVERIFY(held);
    std::vector<std::uint32_t> leaves(held->size());
    for (std::uint32_t i = 0; i < leaves.size(); ++i) leaves[i] = i;
    QVERIFY(document.setLabels(id, AnnotationLayer::Material, leaves, 3, QStringLiteral("Paint")));

    // The plate's sources carry the document's labels, not the file's zeros.
    const auto sources = app::PlateActions::sourcesOf(document);
    auto plate = plate::composePlate(*sources, spec(20), {});
    QVERIFY2(plate.ok(), plate.ok() ? "" : plate.error().message.c_str());
    const auto& classes = plate->panels[0].image.classes;
    QVERIFY(std::count(classes.begin(), classes.end(), std::uint8_t(3)) > 0);
    QCOMPARE(plate->panels[0].image.channels, 3); // tinted in the legend's colour

    app::PlateActions& actions = bench.actions;
    QVERIFY(actions.plateAction()->isEnabled());
    QVERIFY(!actions.exportDeveloppee(m_dir.filePath(QStringLiteral("none.png"))));
    QSignalSpy finished(&actions, &app::PlateActions::plateFinished);
    const QString pdf = m_dir.filePath(QStringLiteral("plate.pdf"));
    actions.exportPlate(spec(20), pdf);
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).toBool(), true);
    QFile file(pdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(5), QByteArray("%PDF-"));

    // Kept in the project: one undo step, saved and read back.
    const int steps = document.undoStack()->count();
    QVERIFY(document.setPlate(spec(20)));
    QVERIFY(!document.setPlate(spec(20)));
    QCOMPARE(document.undoStack()->count(), steps + 1);
    const QString project = m_dir.filePath(QStringLiteral("p.stylos"));
    QString error;
    QVERIFY2(document.saveAs(project, &error), qPrintable(error));
    const auto loaded = core::scene::ProjectFile::load(project.toStdString());
    QVERIFY(loaded.ok());
    QVERIFY(loaded->scene.plate().has_value());
    QCOMPARE(*loaded->scene.plate(), spec(20));
    document.undoStack()->undo();
    QVERIFY(!document.scene().plate().has_value());
}

namespace {
/** The 3D view's camera looking down (w x y z). */
std::optional<std::array<double, 4>> topCamera()
{
    const Eigen::Quaterniond top = core::view::Camera::standardOrientation(core::view::StandardView::Top);
    return std::array<double, 4>{top.w(), top.x(), top.y(), top.z()};
}
} // namespace

void PlateExportTest::viewImageIsTheChosenWidthAlongTheCamera()
{
    PlateBench bench;
    QVERIFY(addDrum(bench.document) != 0);
    app::PlateActions& actions = bench.actions;
    QSignalSpy finished(&actions, &app::PlateActions::plateFinished);
    const QString png = m_dir.filePath(QStringLiteral("view.png"));
    actions.exportViewImage(800, png); // no camera source: refused at once
    QCOMPARE(finished.count(), 1);
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QVERIFY(!QFile::exists(png));

    actions.setCameraSource(topCamera);
    actions.exportViewImage(800, png);
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(1).at(0).toBool(), true);
    const QImage image(png);
    QCOMPARE(image.width(), 800);
    // From the top, a drum (tilted a few degrees by the generator) is nearly a disc, and its centre is drawn.
    QVERIFY2(std::abs(image.height() - 800) <= 80, qPrintable(QString::number(image.height())));
    QVERIFY(qGray(image.pixel(400, image.height() / 2)) < 255);
    QCOMPARE(qGray(image.pixel(2, 2)), 255); // paper in the corner
}

void PlateExportTest::aCancelledExportIsNoError()
{
    // Cancelled from the Tasks dock, or by quitting: said in the log, never in an error box (a box that came up
    // after the window had closed kept the application running without a window).
    PlateBench bench;
    QVERIFY(addDrum(bench.document) != 0);
    app::PlateActions& actions = bench.actions;
    actions.setCameraSource(topCamera);
    QSignalSpy finished(&actions, &app::PlateActions::plateFinished);
    QSignalSpy reported(&actions, &app::PlateActions::reported);
    const QString png = m_dir.filePath(QStringLiteral("cancelled.png"));
    actions.exportViewImage(12000, png);
    bench.tasks.cancelAll();
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QCOMPARE(reported.count(), 1);
    QCOMPARE(reported.at(0).at(0).toString(),
             QStringLiteral("Rendering the view image %1 was cancelled").arg(QDir::toNativeSeparators(png)));
    QCOMPARE(reported.at(0).at(1).toBool(), false);
    QVERIFY(!QFile::exists(png));

    // Too large: the error names the image asked for.
    reported.clear();
    actions.exportViewImage(100000, png);
    QVERIFY(finished.wait(60000));
    QCOMPARE(reported.count(), 1);
    QVERIFY2(reported.at(0).at(0).toString().startsWith(
                 QStringLiteral("Could not render the view image %1: ").arg(QDir::toNativeSeparators(png))),
             qPrintable(reported.at(0).at(0).toString()));
    QCOMPARE(reported.at(0).at(1).toBool(), true);
}

void PlateExportTest::theDefaultPlateFitsItsPage()
{
    // The plate offered when a project has none: the first fragment's développée at the most detailed usual scale
    // that fits by its octree's box (1:10 left the demo's drum, 3.5 m round, wider than A4: Export was refused on
    // first opening).
    widgets::TaskManager tasks;
    widgets::SceneDocument document(tasks);
    QVERIFY(addDrum(document) != 0);
    const auto sources = app::PlateActions::sourcesOf(document);
    const core::plate::PlateSpec spec = widgets::PlateDialog::defaultSpec(*sources);
    QCOMPARE(spec.panels.size(), std::size_t{1});
    // This drum (tilted a few degrees by the generator, so its box is wider than the drum): π × its box's width is
    // over A4's 267 mm in landscape at 1:10; 1:20 is the first usual scale that fits by its box.
    QCOMPARE(spec.panels[0].scale, 20.0);
    auto fits = plate::composePlate(*sources, spec, {});
    QVERIFY2(fits.ok(), fits.ok() ? "" : fits.error().message.c_str());
}

// The plate offered when a project has none is of the fragment the user works on (the scene's current row), hidden
// or not, with the layer painted on it; before, always the first visible fragment with no layer, whatever was
// selected and painted.
void PlateExportTest::theDefaultPlateShowsTheCurrentFragmentAndItsPaint()
{
    widgets::TaskManager tasks;
    widgets::SceneDocument document(tasks);
    // The drum's octree as it was built (another test saves labels into m_octree).
    const auto drum = addDrum(document, "Drum 2", m_unpainted);
    const auto piece = addDrum(document, "Piece B", m_unpainted);
    QVERIFY(drum != 0 && piece != 0);
    QVERIFY(document.setFragmentVisible(piece, false));
    const auto paint = [&document](core::scene::FragmentId id, AnnotationLayer layer) {
        std::vector<std::uint32_t> leaves(3000); // a patch: the first leaves in Morton order
        for (std::uint32_t i = 0; i < leaves.size(); ++i) leaves[i] = i;
        return document.setLabels(id, layer, leaves, 2, QStringLiteral("Paint"));
    };
    QVERIFY(paint(piece, AnnotationLayer::Toolmark));

    auto sources = app::PlateActions::sourcesOf(document);
    // No fragment preferred, or one that is not there: the first visible one, unnamed, and nothing painted on it.
    for (const std::optional<std::size_t> preferred : {std::optional<std::size_t>(), std::optional<std::size_t>(7)}) {
        const cp::PlateSpec plain = widgets::PlateDialog::defaultSpec(*sources, {}, preferred);
        QCOMPARE(plain.panels.size(), std::size_t{1});
        QCOMPARE(plain.panels[0].fragment, std::string());
        QVERIFY(!plain.panels[0].layer);
        QCOMPARE(plain.panels[0].scale, 20.0);
    }
    const cp::PlateSpec chosen = widgets::PlateDialog::defaultSpec(*sources, {}, 1);
    QCOMPARE(chosen.panels[0].fragment, std::string("Piece B"));
    QCOMPARE(chosen.panels[0].layer, std::optional(AnnotationLayer::Toolmark));
    QCOMPARE(chosen.panels[0].scale, 20.0);
    auto drawn = plate::composePlate(*sources, chosen, {});
    QVERIFY2(drawn.ok(), drawn.ok() ? "" : drawn.error().message.c_str());
    const auto& classes = drawn->panels[0].image.classes;
    QVERIFY(std::count(classes.begin(), classes.end(), std::uint8_t(2)) > 0); // the hidden piece's paint is drawn

    // Material painted too: material comes first.
    QVERIFY(paint(piece, AnnotationLayer::Material));
    sources = app::PlateActions::sourcesOf(document);
    QCOMPARE(widgets::PlateDialog::defaultSpec(*sources, {}, 1).panels[0].layer, std::optional(AnnotationLayer::Material));
}

// The plate's développée of a fragment is the one the Développée dock shows: the dock's last result's settings
// (its axis guide, pixel size, directions…) go to the plate; without one (or one of another octree), the fragment's
// axis guide. Before, the plate fitted an axis of its own: the same painted patch stood ~115° apart on the two.
void PlateExportTest::aPlateUnrollsAsTheDockDoes()
{
    widgets::TaskManager tasks;
    widgets::SceneDocument document(tasks);
    const auto id = addDrum(document);
    QVERIFY(id != 0);
    QVERIFY(app::PlateActions::sourcesOf(document)->fragments[0].unrolling == std::nullopt); // no guide, no result

    const auto fitted = core::developpee::computeDeveloppee(m_octree.toStdString(), {});
    QVERIFY2(fitted.ok(), fitted.ok() ? "" : fitted.error().message.c_str());
    const core::unroll::Axis axis = fitted->map.surface().axis(); // the drum's (tilted by the generator)
    QVERIFY(document.setFragmentGuides(id, {{"axis", core::scene::GuideKind::Axis, core::scene::toArray(axis.point),
                                             core::scene::toArray(axis.direction)}}));
    auto unrolling = app::PlateActions::sourcesOf(document)->fragments[0].unrolling;
    QVERIFY(unrolling && unrolling->axis);
    QCOMPARE(unrolling->axis->point, axis.point);
    QCOMPARE(unrolling->axis->direction, axis.direction);
    QVERIFY(!unrolling->pixelSize);

    // The dock's result, about that guide, at 2 cm pixels and 8 directions.
    widgets::DeveloppeeResult shown;
    shown.fragmentId = id;
    shown.octreePath = m_octree;
    shown.settings.axis = axis;
    shown.settings.pixelSize = 0.02;
    shown.settings.directions = 8;
    auto computed = core::developpee::computeDeveloppee(m_octree.toStdString(), shown.settings.options());
    QVERIFY2(computed.ok(), computed.ok() ? "" : computed.error().message.c_str());
    shown.map = computed->map;
    QVERIFY(document.setDeveloppee(id, std::make_shared<const widgets::DeveloppeeResult>(shown)));
    unrolling = app::PlateActions::sourcesOf(document)->fragments[0].unrolling;
    QVERIFY(unrolling && unrolling->axis);
    QCOMPARE(unrolling->axis->direction, axis.direction);
    QCOMPARE(unrolling->pixelSize, std::optional<double>(0.02));
    QCOMPARE(unrolling->directions, 8);

    // The guide changed since (turned end for end): the dock's result is about an axis the fragment no longer has,
    // so the plate takes the guide's.
    QVERIFY(document.setFragmentGuides(id, {{"axis", core::scene::GuideKind::Axis, core::scene::toArray(axis.point),
                                             core::scene::toArray(-axis.direction)}}));
    unrolling = app::PlateActions::sourcesOf(document)->fragments[0].unrolling;
    QVERIFY(unrolling && unrolling->axis);
    QCOMPARE(unrolling->axis->direction, Eigen::Vector3d(-axis.direction));
    QVERIFY(!unrolling->pixelSize);
    QVERIFY(document.setFragmentGuides(id, {{"axis", core::scene::GuideKind::Axis, core::scene::toArray(axis.point),
                                             core::scene::toArray(axis.direction)}}));
    QCOMPARE(app::PlateActions::sourcesOf(document)->fragments[0].unrolling->pixelSize, std::optional<double>(0.02));

    // A result of another octree (the fragment's file was replaced since) is not the fragment's: its guide again.
    shown.octreePath = m_octree + QStringLiteral(".old");
    QVERIFY(document.setDeveloppee(id, std::make_shared<const widgets::DeveloppeeResult>(shown)));
    unrolling = app::PlateActions::sourcesOf(document)->fragments[0].unrolling;
    QVERIFY(unrolling && unrolling->axis);
    QCOMPARE(unrolling->axis->direction, axis.direction);
    QVERIFY(!unrolling->pixelSize);
    QVERIFY(!app::PlateActions::sourcesOf(document)->fragments[0].drumGuides); // an axis guide without flutes

    // With flute guides too (Fit drum guides), the plate fits the drum guides' radius as the dock does.
    std::vector<core::scene::Guide> fluted{{"axis", core::scene::GuideKind::Axis, core::scene::toArray(axis.point),
                                            core::scene::toArray(axis.direction)}};
    for (int k = 0; k < 3; ++k)
        fluted.push_back({"flute", core::scene::GuideKind::Groove, core::scene::toArray(axis.point), core::scene::toArray(axis.direction)});
    QVERIFY(document.setFragmentGuides(id, fluted));
    const auto drumGuides = app::PlateActions::sourcesOf(document)->fragments[0].drumGuides;
    QVERIFY(drumGuides);
    QCOMPARE(QString::fromStdString(drumGuides->octree.string()), m_octree);
    QCOMPARE(drumGuides->options.flutes, 3);
}

STYLOS_WIDGET_TEST_MAIN(PlateExportTest)
#include "PlateExportTest.moc"
