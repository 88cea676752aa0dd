// Import options in the workbench: the dialog's up axis and unit (and what QSettings keeps of them), the
// importer building the octree in that frame (Z up, metres) and the fragment keeping it through a project's
// save and reopen; the Happy Buddha, Y up in its file, imported with up +Y stands along Z.
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/view/GuideGeometry.h"
#include "stylos/widgets/document/FragmentPropertiesWidget.h"
#include "stylos/widgets/document/ImportOptionsDialog.h"
#include "stylos/widgets/document/ScanImporter.h"
#include "stylos/widgets/document/SceneDocument.h"
#include "stylos/widgets/tasks/TaskManager.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>

using stylos::core::io::ImportFrame;
using stylos::core::io::LengthUnit;
using stylos::core::io::UpAxis;
using stylos::widgets::FragmentPropertiesWidget;
using stylos::widgets::ImportOptionsDialog;
using stylos::widgets::ScanImporter;
using stylos::widgets::SceneDocument;
using stylos::widgets::TaskManager;

class ImportOptionsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void theDialogGivesTheChosenAxisAndUnit();
    void theChoiceIsRememberedInTheSettings();
    void anImportIsBuiltInTheFrameAndTheProjectKeepsIt();
    void theHappyBuddhaStandsUpWithUpPlusY();

private:
    QTemporaryDir m_dir;
    stylos::core::octree::BuildOptions m_options;
};

void ImportOptionsTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_options.depth = 6;
    m_options.threads = 2;
}

void ImportOptionsTest::theDialogGivesTheChosenAxisAndUnit()
{
    const ImportFrame given{UpAxis::NegX, LengthUnit::Centimetre, {1, 2, 3}};
    ImportOptionsDialog dialog(given);
    QCOMPARE(dialog.upBox()->count(), 6);
    QCOMPARE(dialog.unitBox()->count(), 3);
    QCOMPARE(dialog.upBox()->currentData().toString(), QStringLiteral("-X"));
    QCOMPARE(dialog.unitBox()->currentData().toString(), QStringLiteral("cm"));
    QVERIFY(dialog.frame() == given);  // the offset passes through

    dialog.upBox()->setCurrentIndex(dialog.upBox()->findData(QStringLiteral("+Y")));
    dialog.unitBox()->setCurrentIndex(dialog.unitBox()->findData(QStringLiteral("mm")));
    const ImportFrame chosen = dialog.frame();
    QVERIFY(chosen.up == UpAxis::PosY);
    QVERIFY(chosen.unit == LengthUnit::Millimetre);
    QCOMPARE(chosen.offset, given.offset);
    // The site offset: three boxes in the scans' unit, to the millimetre of a UTM easting.
    dialog.offsetBox(0)->setValue(512000.125);
    dialog.offsetBox(1)->setValue(-4100000.5);
    dialog.offsetBox(2)->setValue(0);
    QCOMPARE(dialog.frame().offset, (std::array<double, 3>{512000.125, -4100000.5, 0.0}));
    // Typed as scientific notation too (the plain spin box read "4.1e6" as 4.16); applied on leaving the field.
    dialog.show();
    dialog.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&dialog));
    dialog.offsetBox(2)->setFocus();
    dialog.offsetBox(2)->selectAll();
    QTest::keyClicks(dialog.offsetBox(2), QStringLiteral("-4.1e6"));
    QTest::keyClick(dialog.offsetBox(2), Qt::Key_Tab);
    QCOMPARE(dialog.frame().offset, (std::array<double, 3>{512000.125, -4100000.5, -4100000.0}));
    // Out of range (1e9 at most): not applied, nor any prefix typed on the way (it kept 10, from "1e1").
    dialog.offsetBox(2)->setFocus();
    dialog.offsetBox(2)->selectAll();
    QTest::keyClicks(dialog.offsetBox(2), QStringLiteral("1e12"));
    QTest::keyClick(dialog.offsetBox(2), Qt::Key_Tab);
    QCOMPARE(dialog.frame().offset[2], -4100000.0);
    dialog.offsetBox(2)->setValue(0);
    // Every item names its axis; OK accepts.
    for (int i = 0; i < dialog.upBox()->count(); ++i)
        QVERIFY2(dialog.upBox()->itemText(i).contains(dialog.upBox()->itemData(i).toString().right(1)),
                 qPrintable(dialog.upBox()->itemText(i)));
    dialog.show();
    dialog.buttons()->button(QDialogButtonBox::Ok)->click();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
}

void ImportOptionsTest::theChoiceIsRememberedInTheSettings()
{
    QSettings store(m_dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
    QVERIFY(ImportOptionsDialog::load(store) == ImportFrame{});  // nothing saved: Z up, metres
    ImportOptionsDialog::save(store, {UpAxis::NegY, LengthUnit::Millimetre, {}});
    QCOMPARE(store.value(QStringLiteral("import/up")).toString(), QStringLiteral("-Y"));
    QCOMPARE(store.value(QStringLiteral("import/unit")).toString(), QStringLiteral("mm"));
    QVERIFY((ImportOptionsDialog::load(store) == ImportFrame{UpAxis::NegY, LengthUnit::Millimetre, {}}));
    const ImportFrame site{UpAxis::PosZ, LengthUnit::Metre, {512000.25, -4.5e6, 12.5}};
    ImportOptionsDialog::save(store, site);
    QVERIFY(ImportOptionsDialog::load(store) == site);
    store.setValue(QStringLiteral("import/offset"), QVariantList{1, QStringLiteral("x"), 3}); // not numbers: no offset
    QCOMPARE(ImportOptionsDialog::load(store).offset, (std::array<double, 3>{0.0, 0.0, 0.0}));
    // A value this version does not know keeps its default.
    store.setValue(QStringLiteral("import/up"), QStringLiteral("sideways"));
    store.setValue(QStringLiteral("import/unit"), QStringLiteral("ell"));
    QVERIFY(ImportOptionsDialog::load(store) == ImportFrame{});
}

void ImportOptionsTest::anImportIsBuiltInTheFrameAndTheProjectKeepsIt()
{
    // A slab 40 mm wide, 200 mm tall along the file's Y, 20 mm deep, in millimetres, with normals.
    QString text = QStringLiteral("# x y z nx ny nz\n");
    for (int i = 0; i <= 40; i += 2)
        for (int j = 0; j <= 200; j += 2)
            for (int k = 0; k <= 20; k += 10) text += QStringLiteral("%1 %2 %3 0 0 1\n").arg(i).arg(j).arg(k);
    const QString scan = stylos::test::writeFile(m_dir.path(), QStringLiteral("slab.xyz"), text.toUtf8());
    const QString project = m_dir.filePath(QStringLiteral("project"));
    QVERIFY(QDir().mkpath(project));

    TaskManager tasks;
    SceneDocument doc(tasks);
    QString error;
    QVERIFY2(doc.saveAs(project + QStringLiteral("/site.stylos"), &error), qPrintable(error));
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    const ImportFrame frame{UpAxis::PosY, LengthUnit::Millimetre, {}};
    importer.setImportFrame(frame);
    QCOMPARE(importer.importFiles({scan}), 1);
    QVERIFY(tasks.waitForIdle(60000));
    QCOMPARE(doc.scene().size(), 1u);
    const auto& fragment = doc.scene().fragments()[0];
    QVERIFY(fragment.importFrame == frame);
    const auto octree = doc.octree(fragment.id);
    QVERIFY(octree);
    // Z up, in metres: the root box is the cube around x 0..0.04, y −0.02..0, z 0..0.2.
    QVERIFY(octree->box() == stylos::core::octree::RootBox::enclosing({0, -0.02, 0, 0.04, 0, 0.2}));
    QVERIFY2(doc.save(&error), qPrintable(error));

    SceneDocument reopened(tasks);
    QSignalSpy loaded(&reopened, &SceneDocument::loadingFinished);
    QVERIFY2(reopened.open(project + QStringLiteral("/site.stylos"), &error), qPrintable(error));
    QVERIFY(loaded.wait(10000));
    QCOMPARE(reopened.scene(), doc.scene());
    QVERIFY(reopened.scene().fragments()[0].importFrame == frame);
    QVERIFY(reopened.octree(fragment.id));
    QVERIFY(reopened.octree(fragment.id)->box() == octree->box());

    // The Properties dock says how it was imported.
    FragmentPropertiesWidget properties(reopened);
    properties.setFragment(fragment.id);
    QCOMPARE(properties.importedLabel()->text(), QStringLiteral("+Y up, in mm"));
    reopened.setFragmentVisible(fragment.id, false);  // any change refreshes it: still there
    QCOMPARE(properties.importedLabel()->text(), QStringLiteral("+Y up, in mm"));
}

void ImportOptionsTest::theHappyBuddhaStandsUpWithUpPlusY()
{
    const QString buddha = QStringLiteral(STYLOS_SHARED_DATA "/scans/happy_buddha_1.1M.ply");
    if (!QFileInfo::exists(buddha)) QSKIP("../shared/data is absent: real-scan test skipped");
    TaskManager tasks;
    SceneDocument doc(tasks);
    ScanImporter importer(doc, tasks);
    importer.setBuildOptions(m_options);
    importer.setCacheDirectory(m_dir.filePath(QStringLiteral("cache")));
    importer.setImportFrame({UpAxis::PosY, LengthUnit::Metre, {}});
    QSignalSpy finished(&importer, &ScanImporter::importsFinished);
    QCOMPARE(importer.importFiles({buddha}), 1);
    QVERIFY(tasks.waitForIdle(240000));
    QCOMPARE(finished.size(), 1);
    QCOMPARE(finished.at(0).at(0).toStringList(), QStringList());
    QCOMPARE(doc.scene().size(), 1u);
    const auto octree = doc.octree(doc.scene().fragments()[0].id);
    QVERIFY(octree);
    // In its file the Buddha is 0.200 m along Y, 0.082 m along X and Z; turned, its height is along Z.
    const Eigen::Vector3d size = stylos::core::view::occupiedBounds(*octree, 6).sizes();
    QVERIFY2(size.z() > 2 * size.x() && size.z() > 2 * size.y(),
             qPrintable(QStringLiteral("%1 x %2 x %3").arg(size.x()).arg(size.y()).arg(size.z())));
    QVERIFY(std::abs(size.z() - 0.200024) < 2 * octree->box().size / 64);
}

STYLOS_WIDGET_TEST_MAIN(ImportOptionsTest)
#include "ImportOptionsTest.moc"
