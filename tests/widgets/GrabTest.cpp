// The `stylos` executable's automation: --grab OUT.png [FILES] waits for the scene, its tasks and the
// refined view, writes a PNG of the window in which the drum is visible and exits 0, or 1 naming the file
// that failed; --orbit-benchmark N FILE and --pose-benchmark N FILE print the frame times as JSON; --version
// and --help.
#include "DrumOctreeFixture.h"
#include "SceneTestSupport.h"
#include "WidgetTestSupport.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <QImage>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>

class GrabTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void versionAndHelp();
    void grabsTheDrumInTheView();
    void grabsTheDemoScene();
    void failsNamingTheBadFile();
    void aDockWhoseGuidesCannotBeFittedEndsNamingWhy();
    void orbitBenchmarkPrintsFrameTimes();
    void poseBenchmarkPrintsFrameTimes();
    void rejectsBadOptions();

private:
    /** Runs stylos with @p args; returns its exit code, stdout and stderr. */
    int run(const QStringList& args, QString* out = nullptr, QString* err = nullptr, int timeoutMs = 60000);
    /** Distinct colours in a grid of samples of @p image: 1 means blank. */
    static int distinctColours(const QImage& image);

    /** The 3D view can be created here (an X display; Qt's offscreen platform has no GL widget). */
    static bool hasDisplay() { return !qEnvironmentVariableIsEmpty("DISPLAY"); }

    QTemporaryDir m_dir;
    stylos::test::DrumOctree m_drum;
};

void GrabTest::initTestCase()
{
    QVERIFY(QFileInfo(STYLOS_EXECUTABLE).isExecutable());
    QVERIFY(m_dir.isValid());
    m_drum = stylos::test::makeDrumOctree(m_dir.path());
}

int GrabTest::run(const QStringList& args, QString* out, QString* err, int timeoutMs)
{
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    // Never the user's cache or settings: the demo is generated under the test's folder.
    env.insert("XDG_CACHE_HOME", m_dir.filePath("cache"));
    env.insert("XDG_CONFIG_HOME", m_dir.filePath("config"));
    env.insert("LC_ALL", "C");
    process.setProcessEnvironment(env);
    process.start(STYLOS_EXECUTABLE, args);
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        return -1;
    }
    if (out) *out = QString::fromLocal8Bit(process.readAllStandardOutput());
    if (err) *err = QString::fromLocal8Bit(process.readAllStandardError());
    return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
}

int GrabTest::distinctColours(const QImage& image)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

void GrabTest::versionAndHelp()
{
    QString out;
    QCOMPARE(run({"--version"}, &out), 0);
    QVERIFY2(out.contains(STYLOS_VERSION), qPrintable(out));
    QCOMPARE(run({"--help"}, &out), 0);
    QVERIFY(out.contains("--grab"));
}

void GrabTest::grabsTheDrumInTheView()
{
    const QString png = m_dir.filePath("drum.png");
    QString err;
    QCOMPARE(run({"--grab", png, QString::fromStdString(m_drum.poct.string())}, nullptr, &err), 0);
    QVERIFY2(!err.contains("stylos:"), qPrintable(err));
    const QImage image(png);
    QVERIFY2(!image.isNull(), qPrintable(err));
    QVERIFY(image.width() >= 640 && image.height() >= 400);
    QVERIFY(distinctColours(image) > 8);
    if (!hasDisplay()) QSKIP("no display: the 3D view is not created");
    // The drum fills the middle of the view after the fit: its centre column differs from the corners'
    // background, and is shaded (many greys), not one flat colour.
    const QImage view = image.copy(image.width() / 4, image.height() / 4, image.width() / 2, image.height() / 2);
    const QRgb background = image.pixel(image.width() / 2, image.height() / 6);
    QSet<QRgb> shades;
    int drum = 0;
    for (int y = 0; y < view.height(); y += 3)
        for (int x = view.width() / 3; x < 2 * view.width() / 3; x += 3) {
            const QRgb c = view.pixel(x, y);
            if (qAbs(qGray(c) - qGray(background)) > 20) { ++drum; shades.insert(c); }
        }
    QVERIFY2(drum > 200, qPrintable(QString::number(drum)));
    QVERIFY2(shades.size() > 20, qPrintable(QString::number(shades.size())));
}

void GrabTest::grabsTheDemoScene()
{
    const QString png = m_dir.filePath("demo.png");
    QString err;
    QCOMPARE(run({"--grab", png}, nullptr, &err, 280000), 0);
    QVERIFY2(!err.contains("stylos:"), qPrintable(err)); // no error reported
    const QImage image(png);
    QVERIFY(!image.isNull());
    QVERIFY(distinctColours(image) > 8);
    QVERIFY(QFileInfo(m_dir.filePath("cache/Stylos/stylos/demo/demo.stylos")).isFile());
}

void GrabTest::failsNamingTheBadFile()
{
    const QString bad = stylos::test::writeFile(m_dir.path(), "broken-capital.ply", "garbage");
    const QString png = m_dir.filePath("bad.png");
    QString err;
    QCOMPARE(run({"--grab", png, bad}, nullptr, &err), 1);
    QVERIFY2(err.contains("broken-capital.ply"), qPrintable(err));
}

void GrabTest::aDockWhoseGuidesCannotBeFittedEndsNamingWhy()
{
    // --dock on two fragments (no drum among them): the first one's guide fit finds no flutes, and the run ends with
    // exit 1 naming it (it waited for ever for flutes).
    if (!hasDisplay()) QSKIP("no display: the 3D view is not created");
    const QString piece = stylos::test::makeOctreeFile(m_dir.path(), QStringLiteral("piece.poct"));
    QString err;
    QCOMPARE(run({"--grab", m_dir.filePath("dock.png"), "--dock", piece, piece}, nullptr, &err, 100000), 1);
    QVERIFY2(err.contains("stylos: Could not fit the guides of piece"), qPrintable(err));
    QVERIFY(!QFile::exists(m_dir.filePath("dock.png")));
}

void GrabTest::orbitBenchmarkPrintsFrameTimes()
{
    if (!hasDisplay()) QSKIP("no display: the 3D view is not created");
    QString out, err;
    QCOMPARE(run({"--orbit-benchmark", "5", QString::fromStdString(m_drum.poct.string())}, &out, &err), 0);
    const QJsonObject result = QJsonDocument::fromJson(out.toUtf8()).object();
    QVERIFY2(!result.isEmpty(), qPrintable(out + err));
    QCOMPARE(result.value("frames").toInt(), 5);
    QCOMPARE(result.value("width").toInt(), 1280);
    QCOMPARE(result.value("height").toInt(), 800);
    QVERIFY(result.value("medianMs").toDouble() > 0);
    QVERIFY(result.value("p95Ms").toDouble() >= result.value("medianMs").toDouble());
    QVERIFY(result.value("maxPointsDrawn").toDouble() > 0);
    QVERIFY(result.value("openToFirstFrameMs").toDouble() > 0);
}

void GrabTest::poseBenchmarkPrintsFrameTimes()
{
    if (!hasDisplay()) QSKIP("no display: the 3D view is not created");
    QString out, err;
    QCOMPARE(run({"--pose-benchmark", "5", QString::fromStdString(m_drum.poct.string())}, &out, &err), 0);
    const QJsonObject result = QJsonDocument::fromJson(out.toUtf8()).object();
    QVERIFY2(!result.isEmpty(), qPrintable(out + err));
    QCOMPARE(result.value("frames").toInt(), 5);
    QCOMPARE(result.value("width").toInt(), 1280);
    QCOMPARE(result.value("height").toInt(), 800);
    QCOMPARE(result.value("fragmentId").toDouble(), 1.0); // the first fragment of the new project
    QCOMPARE(result.value("degreesPerFrame").toDouble(), 1.0);
    // Five poses start no cut of their own (before the pose-only push each frame restarted one: 353 cuts in 360
    // frames). Under load the budget controller starts some as frames slow down, which is not the pose's doing:
    // measured 0–1 at load ~2, 3 with frames of 230–380 ms at load 6 (two other builds beside ctest -j2).
    QVERIFY2(result.value("cutsStarted").toDouble() <= 3.0, qPrintable(out));
    QVERIFY(result.value("medianMs").toDouble() > 0);
    QVERIFY(result.value("p95Ms").toDouble() >= result.value("medianMs").toDouble());
    QVERIFY(result.value("maxPointsDrawn").toDouble() > 0);
    QVERIFY(!result.contains("error"));
}

void GrabTest::rejectsBadOptions()
{
    QString err;
    QCOMPARE(run({"--orbit-benchmark", "many", "x.poct"}, nullptr, &err), 2);
    QVERIFY2(err.contains("many"), qPrintable(err));
    QCOMPARE(run({"--orbit-benchmark", "5"}, nullptr, &err), 2);
    QVERIFY2(err.contains("exactly one file"), qPrintable(err));
    QCOMPARE(run({"--pose-benchmark", "0", "x.poct"}, nullptr, &err), 2);
    QVERIFY2(err.contains("--pose-benchmark: '0'"), qPrintable(err));
    QCOMPARE(run({"--pose-benchmark", "5", "a.poct", "b.poct"}, nullptr, &err), 2);
    QVERIFY2(err.contains("--pose-benchmark needs exactly one file"), qPrintable(err));
    QCOMPARE(run({"--pose-benchmark", "5", "--orbit-benchmark", "5", "x.poct"}, nullptr, &err), 2);
    QVERIFY2(err.contains("neither --grab nor --orbit-benchmark"), qPrintable(err));
}

STYLOS_WIDGET_TEST_MAIN(GrabTest)
#include "GrabTest.moc"
