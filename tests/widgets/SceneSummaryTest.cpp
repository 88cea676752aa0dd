// SceneSummaryModel and SceneSummaryWidget: one row per file, an exact total, a file loaded again
// replaces its row.
#include "WidgetTestSupport.h"

#include "stylos/widgets/SceneSummaryModel.h"
#include "stylos/widgets/SceneSummaryWidget.h"

#include <QLocale>
#include <QSignalSpy>
#include <QTableView>

using stylos::widgets::ScanSummary;
using stylos::widgets::SceneSummaryModel;
using stylos::widgets::SceneSummaryWidget;

namespace {

ScanSummary makeScan(const QString& path, std::uint64_t points)
{
    ScanSummary scan;
    scan.path = path;
    scan.format = "ply-ascii";
    scan.points = points;
    scan.skipped = 2;
    scan.bounds = {0, 0, 0, 1.5, 2, 0.25};
    scan.attributes = QStringList{"normal", "intensity"};
    return scan;
}

} // namespace

class SceneSummaryTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void modelListsFilesAndTotal();
    void reloadingAFileReplacesItsRow();
    void widgetShowsTheTotal();
    void columnsFitTheirContents();
};

void SceneSummaryTest::modelListsFilesAndTotal()
{
    SceneSummaryModel model;
    QSignalSpy total(&model, &SceneSummaryModel::totalPointsChanged);
    model.addScan(makeScan("/data/drum.ply", 3'000'000'123ull));
    model.addScan(makeScan("/data/fragment.las", 77));
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.columnCount(), int(SceneSummaryModel::ColumnCount));
    QCOMPARE(model.totalPoints(), 3'000'000'200ull);
    QCOMPARE(total.size(), 2);
    QCOMPARE(total.last().at(0).toULongLong(), 3'000'000'200ull);

    const QLocale locale;
    QCOMPARE(model.index(0, SceneSummaryModel::FileColumn).data().toString(), QString("drum.ply"));
    QCOMPARE(model.index(0, SceneSummaryModel::FormatColumn).data().toString(), QString("ply-ascii"));
    QCOMPARE(model.index(0, SceneSummaryModel::PointsColumn).data().toString(), locale.toString(3'000'000'123ull));
    QCOMPARE(model.index(1, SceneSummaryModel::SkippedColumn).data().toString(), locale.toString(2));
    QCOMPARE(model.index(1, SceneSummaryModel::AttributesColumn).data().toString(), QString("normal, intensity"));
    QVERIFY(model.index(1, SceneSummaryModel::SizeColumn).data().toString().contains(locale.toString(1.5, 'f', 3)));
    QCOMPARE(model.index(1, SceneSummaryModel::FileColumn).data(Qt::ToolTipRole).toString(),
             QString("/data/fragment.las"));

    model.clear();
    QCOMPARE(model.rowCount(), 0);
    QCOMPARE(model.totalPoints(), 0u);
}

void SceneSummaryTest::reloadingAFileReplacesItsRow()
{
    SceneSummaryModel model;
    model.addScan(makeScan("/a.ply", 10));
    model.addScan(makeScan("/b.ply", 20));
    model.addScan(makeScan("/a.ply", 15));
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.totalPoints(), 35u);
    QCOMPARE(model.scan(0).points, 15u);
}

void SceneSummaryTest::widgetShowsTheTotal()
{
    SceneSummaryModel model;
    SceneSummaryWidget widget(model);
    widget.show();
    QVERIFY(QTest::qWaitForWindowExposed(&widget));
    QVERIFY(!widget.totalText().isEmpty());
    QVERIFY(!widget.totalText().contains(QLocale().toString(0)));

    model.addScan(makeScan("/a.ply", 1'234'567));
    model.addScan(makeScan("/b.ply", 3));
    QVERIFY2(widget.totalText().contains(QLocale().toString(1'234'570)), qPrintable(widget.totalText()));
    QVERIFY(widget.totalText().contains("2 file"));
    QCOMPARE(widget.table()->model()->rowCount(), 2);
}

void SceneSummaryTest::columnsFitTheirContents()
{
    SceneSummaryModel model;
    SceneSummaryWidget widget(model);
    widget.resize(900, 400);
    widget.show();
    QVERIFY(QTest::qWaitForWindowExposed(&widget));
    model.addScan(makeScan("/a-long-file-name-for-the-first-scan.ply", 1));
    model.clear(); // the demo replaces the scene: the columns must fit again afterwards
    model.addScan(makeScan("/another-long-file-name-for-a-drum.ply", 123'456'789));
    QTableView* table = widget.table();
    const QFontMetrics metrics(table->font());
    const int nameWidth = metrics.horizontalAdvance("another-long-file-name-for-a-drum.ply");
    QTRY_VERIFY2(table->columnWidth(SceneSummaryModel::FileColumn) > nameWidth,
                 qPrintable(QString::number(table->columnWidth(SceneSummaryModel::FileColumn))));
    QVERIFY(table->columnWidth(SceneSummaryModel::PointsColumn) >
            metrics.horizontalAdvance(QLocale().toString(123'456'789)));
}

STYLOS_WIDGET_TEST_MAIN(SceneSummaryTest)
#include "SceneSummaryTest.moc"
