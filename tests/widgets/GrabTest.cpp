// The `stylos` executable's automation: --grab OUT.png [FILES] waits for loading, writes a non-blank
// PNG of the window and exits 0, or 1 naming the file that failed; --version and --help.
#include "WidgetTestSupport.h"

#include <QImage>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>

class GrabTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void versionAndHelp();
    void grabsLoadedFiles();
    void grabsTheDemoScene();
    void failsNamingTheBadFile();

private:
    /** Runs stylos with @p args; returns its exit code, stdout and stderr. */
    int run(const QStringList& args, QString* out = nullptr, QString* err = nullptr, int timeoutMs = 60000);
    /** Distinct colours in a grid of samples of @p image: 1 means blank. */
    static int distinctColours(const QImage& image);

    QTemporaryDir m_dir;
};

void GrabTest::initTestCase()
{
    QVERIFY(QFileInfo(STYLOS_EXECUTABLE).isExecutable());
    QVERIFY(m_dir.isValid());
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

void GrabTest::grabsLoadedFiles()
{
    const QString ply = stylos::test::writeFile(m_dir.path(), "tiny.ply", stylos::test::tinyPly());
    const QString png = m_dir.filePath("tiny.png");
    QString err;
    QCOMPARE(run({"--grab", png, ply}, nullptr, &err), 0);
    const QImage image(png);
    QVERIFY2(!image.isNull(), qPrintable(err));
    QVERIFY(image.width() >= 200 && image.height() >= 100);
    QVERIFY(distinctColours(image) > 8);
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
    QVERIFY(QFileInfo(m_dir.filePath("cache/Stylos/stylos/demo/drum.ply")).isFile());
}

void GrabTest::failsNamingTheBadFile()
{
    const QString bad = stylos::test::writeFile(m_dir.path(), "broken-capital.ply", "garbage");
    const QString png = m_dir.filePath("bad.png");
    QString err;
    QCOMPARE(run({"--grab", png, bad}, nullptr, &err), 1);
    QVERIFY2(err.contains("broken-capital.ply"), qPrintable(err));
}

STYLOS_WIDGET_TEST_MAIN(GrabTest)
#include "GrabTest.moc"
