// What Stylos and Qt say in words, in English, French and Greek: Qt's own dialog buttons and file chooser (Debian
// ships no Qt translation for Greek, so ours carry them, app/gui/QtStandardTexts.cpp), why a plate does not fit
// its page, the docking line of the Log and why a dock failed, each with the language's numbers (decimal comma,
// grouping), a number field made before the switch included.
#include "Translations.h"
#include "WidgetTestSupport.h"

#include "stylos/core/dock/DockRegistration.h"
#include "stylos/core/plate/PlateLayout.h"
#include "stylos/widgets/docking/DockJob.h"
#include "stylos/widgets/plate/PlateDialog.h"
#include "stylos/widgets/util/NumberSpinBox.h"

#include <QAbstractButton>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QtTest>

#include <memory>

using namespace stylos;

class LanguageTextsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void standardButtonsFollowTheLanguage();
    void fileChooserFollowsTheLanguage();
    void aPlateThatDoesNotFitIsSaidInTheLanguage();
    void logLinesWriteNumbersInTheLanguage();
    void aFailedDockSaysWhyAndWhatToDoInTheLanguage();

private:
    void setLanguage(const QString& code);

    std::unique_ptr<app::Translations> m_translations;
};

void LanguageTextsTest::initTestCase()
{
    QSettings().clear();
    m_translations = std::make_unique<app::Translations>();
}

void LanguageTextsTest::cleanup()
{
    setLanguage(QStringLiteral("en"));
    QSettings().clear();
}

void LanguageTextsTest::setLanguage(const QString& code)
{
    QVERIFY(m_translations->setLanguage(code));
    QCoreApplication::processEvents(); // LanguageChange is posted
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

// Qt's own dialog buttons (the plate dialog's Cancel, the delete-class question's Yes / No) in French and Greek:
// Debian ships no Qt translation for Greek, so our translations carry them (app/gui/QtStandardTexts.cpp).
void LanguageTextsTest::standardButtonsFollowTheLanguage()
{
    const QList<QPair<QString, QStringList>> expected{{QStringLiteral("fr"), {QStringLiteral("OK"), QStringLiteral("Annuler"), QStringLiteral("&Oui")}},
                                                      {QStringLiteral("el"), {QStringLiteral("OK"), QStringLiteral("Ακύρωση"), QStringLiteral("&Ναι")}}};
    for (const auto& [code, texts] : expected) {
        setLanguage(code);
        QDialogButtonBox box(QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::Yes);
        QCOMPARE(box.button(QDialogButtonBox::Ok)->text(), texts[0]);
        QCOMPARE(box.button(QDialogButtonBox::Cancel)->text(), texts[1]);
        QCOMPARE(box.button(QDialogButtonBox::Yes)->text(), texts[2]);
    }
    setLanguage(QStringLiteral("en"));
    QDialogButtonBox box(QDialogButtonBox::Cancel);
    QCOMPARE(box.button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Cancel"));
}

// Qt's own file chooser (where the desktop offers no native one): French from Qt's catalogue or ours, Greek from
// ours (app/gui/QtStandardTexts.cpp). Its labels are read as the user sees them.
void LanguageTextsTest::fileChooserFollowsTheLanguage()
{
    const QList<QPair<QString, QStringList>> expected{
        {QStringLiteral("fr"), {QStringLiteral("Voir dans :"), QStringLiteral("&Nom de fichier :"), QStringLiteral("Fichiers de type :")}},
        {QStringLiteral("el"), {QStringLiteral("Αναζήτηση σε:"), QStringLiteral("Όνομα &αρχείου:"), QStringLiteral("Αρχεία τύπου:")}},
        {QStringLiteral("en"), {QStringLiteral("Look in:"), QStringLiteral("File &name:"), QStringLiteral("Files of type:")}}};
    for (const auto& [code, texts] : expected) {
        setLanguage(code);
        QFileDialog chooser;
        chooser.setOption(QFileDialog::DontUseNativeDialog);
        chooser.setAcceptMode(QFileDialog::AcceptSave);
        const QStringList names{QStringLiteral("lookInLabel"), QStringLiteral("fileNameLabel"), QStringLiteral("fileTypeLabel")};
        for (int i = 0; i < names.size(); ++i) {
            auto* label = chooser.findChild<QLabel*>(names[i]);
            QVERIFY2(label, qPrintable(names[i]));
            QCOMPARE(label->text(), texts[i]);
        }
        // The Type column of a folder (Qt 6 asks another context, with a disambiguation).
        QCOMPARE(QCoreApplication::translate("QAbstractFileIconProvider", "Folder", "All other platforms"),
                 code == QStringLiteral("fr")   ? QStringLiteral("Dossier")
                 : code == QStringLiteral("el") ? QStringLiteral("Φάκελος")
                                                : QStringLiteral("Folder"));
        auto* buttons = chooser.findChild<QDialogButtonBox*>(QStringLiteral("buttonBox"));
        QVERIFY(buttons);
        QCOMPARE(buttons->button(QDialogButtonBox::Save)->text(),
                 code == QStringLiteral("fr")   ? QStringLiteral("&Enregistrer")
                 : code == QStringLiteral("el") ? QStringLiteral("&Αποθήκευση")
                                                : QStringLiteral("&Save"));
    }
}

// The Export plate dialog's "does not fit" message in the user's words and numbers (it was the layout's English,
// "panel (developpee, 1:10) is 342.5 × 50.8 mm", in every language).
void LanguageTextsTest::aPlateThatDoesNotFitIsSaidInTheLanguage()
{
    namespace cp = core::plate;
    cp::PlateSpec one;
    one.panels.resize(1);
    one.panels[0].scale = 10;
    cp::LayoutFailure large;
    large.kind = cp::LayoutFailure::Kind::PanelTooLarge;
    large.sizeMm = {342.5, 50.8};
    large.printArea = {15, 15, 267, 180};
    large.page = {297, 210};
    large.smallerScale = 13;
    cp::PlateSpec two = one;
    two.panels.resize(2);
    two.panels[1].view = cp::PanelView::Front;
    two.panels[1].scale = 2.5;
    cp::LayoutFailure tall;
    tall.kind = cp::LayoutFailure::Kind::TooTall;
    tall.sizeMm = {267, 206.5};
    tall.printArea = large.printArea;
    tall.page = large.page;
    tall.fittingScales = {13, 3.5};
    const struct {
        QString code, large, tall;
    } expected[] = {
        {QStringLiteral("fr"),
         QStringLiteral("Le panneau (Développée, 1:10) mesure 342,5 × 50,8 mm ; la zone d’impression mesure 267,0 × 180,0 mm : "
                        "choisissez 1:13 ou une échelle plus petite, ou une page plus grande."),
         QStringLiteral("La planche demande 206,5 mm de hauteur ; la zone d’impression mesure 267,0 × 180,0 mm : choisissez "
                        "des échelles plus petites (A 1:13, B 1:3,5), une page plus grande ou l’autre orientation.")},
        {QStringLiteral("el"),
         QStringLiteral("Το πλαίσιο (Ανάπτυγμα, 1:10) έχει διαστάσεις 342,5 × 50,8 mm· η επιφάνεια εκτύπωσης είναι 267,0 × 180,0 mm: "
                        "επιλέξτε 1:13 ή μικρότερη κλίμακα, ή μεγαλύτερη σελίδα."),
         QStringLiteral("Ο πίνακας χρειάζεται ύψος 206,5 mm· η επιφάνεια εκτύπωσης είναι 267,0 × 180,0 mm: επιλέξτε μικρότερες "
                        "κλίμακες (A 1:13, B 1:3,5), μεγαλύτερη σελίδα ή τον άλλο προσανατολισμό.")},
        {QStringLiteral("en"),
         QStringLiteral("The panel (Développée, 1:10) is 342.5 × 50.8 mm; the print area is 267.0 × 180.0 mm: use 1:13 or smaller, "
                        "or a larger page."),
         QStringLiteral("The plate needs 206.5 mm of height; the print area is 267.0 × 180.0 mm: use smaller scales (A 1:13, "
                        "B 1:3.5), a larger page or the other orientation.")},
    };
    for (const auto& e : expected) {
        setLanguage(e.code);
        QCOMPARE(widgets::PlateDialog::layoutFailureText(large, one), e.large);
        QCOMPARE(widgets::PlateDialog::layoutFailureText(tall, two), e.tall);
    }
    // A caption taller than the print area on its own: no scale offered.
    cp::LayoutFailure wordy = tall;
    wordy.kind = cp::LayoutFailure::Kind::CaptionTooTall;
    wordy.sizeMm = {267, 640.1};
    setLanguage(QStringLiteral("fr"));
    QCOMPARE(widgets::PlateDialog::layoutFailureText(wordy, two),
             QStringLiteral("La légende de figure demande à elle seule 640,1 mm de hauteur ; la zone d’impression mesure "
                            "267,0 × 180,0 mm : raccourcissez-la ou choisissez une page plus grande."));
    setLanguage(QStringLiteral("en"));
    QCOMPARE(widgets::PlateDialog::layoutFailureText(wordy, two),
             QStringLiteral("The caption needs 640.1 mm of height on its own; the print area is 267.0 × 180.0 mm: shorten "
                            "the caption or use a larger page."));
}

// The docking line of the Log writes its numbers as the language does (it wrote "RMS 0.232 mm over 10974 points"
// in Greek, where every other line had "0,232" and "10.974").
void LanguageTextsTest::logLinesWriteNumbersInTheLanguage()
{
    widgets::DockJobResult docked;
    docked.dock.rms = 0.000232;
    docked.dock.inliers = 10974;
    docked.dock.fluteShift = 0.12;
    docked.seconds = 1.5;
    const struct {
        QString code, rms, points;
    } expected[] = {{QStringLiteral("fr"), QStringLiteral("0,232"), QLocale(QLocale::French).toString(10974)},
                    {QStringLiteral("el"), QStringLiteral("0,232"), QStringLiteral("10.974")},
                    {QStringLiteral("en"), QStringLiteral("0.232"), QStringLiteral("10,974")}};
    // A number field made before the switch writes its number the new way too.
    widgets::NumberSpinBox field;
    field.setDecimals(2);
    field.setRange(0, 10);
    field.setValue(1.5);
    for (const auto& e : expected) {
        setLanguage(e.code);
        QCOMPARE(field.text(), e.code == QStringLiteral("en") ? QStringLiteral("1.50") : QStringLiteral("1,50"));
        const QString line = widgets::DockJob::summary(QStringLiteral("fragment"), docked);
        QVERIFY2(line.contains(e.rms) && line.contains(e.points) && line.contains(QLocale().toString(0.12, 'f', 2)),
                 qPrintable(e.code + QStringLiteral(": ") + line));
        QVERIFY2(!line.contains(QStringLiteral("10974")), qPrintable(line));
    }
    // A shift that rounds to nothing is 0.00, not -0.00.
    docked.dock.fluteShift = -0.0004;
    const QString still = widgets::DockJob::summary(QStringLiteral("fragment"), docked);
    QVERIFY2(still.contains(QStringLiteral(" 0.00 ")) && !still.contains(QStringLiteral("-0.00")), qPrintable(still));
    // Far off the profile against the drum's own RMS: said (within 3 times: not).
    docked.drumRms = 0.0001;
    QVERIFY2(!widgets::DockJob::summary(QStringLiteral("fragment"), docked).contains(QStringLiteral("wrong flute")),
             qPrintable(widgets::DockJob::summary(QStringLiteral("fragment"), docked)));
    docked.dock.rms = 0.00232;
    QVERIFY2(widgets::DockJob::summary(QStringLiteral("fragment"), docked)
                 .endsWith(QStringLiteral("; 23.2 times the drum's own RMS: it may rest on the wrong flute or be held off its "
                                          "place by a lock")),
             qPrintable(widgets::DockJob::summary(QStringLiteral("fragment"), docked)));
}

// A dock from too far says so, and what to do, in the user's language (it said "these data and settings do not
// allow it" in Greek, the reason only in English below).
void LanguageTextsTest::aFailedDockSaysWhyAndWhatToDoInTheLanguage()
{
    const core::Error error{core::ErrorCode::InvalidArgument, "fragment.poct: the starting pose is too far from the drum"};
    core::dock::DockFailure far;
    far.kind = core::dock::DockFailure::Kind::TooFar;
    far.reachM = 0.0323;
    core::dock::DockFailure plain;
    plain.kind = core::dock::DockFailure::Kind::NoFlutes;
    plain.strength = 0.04;
    plain.needed = 0.15;
    const struct {
        QString code, far, plain;
    } expected[] = {
        {QStringLiteral("fr"),
         QStringLiteral("Impossible d’amarrer f1 : il est trop loin du tambour ; 0 de ses points sont à moins de 32,3 mm de "
                        "la surface du tambour (il en faut au moins 200). Approchez-le de sa place sur le tambour (l’outil "
                        "Déplacer, ou son placement dans le repère du tambour dans Propriétés) et amarrez-le de nouveau."),
         QStringLiteral("signal des cannelures 0,04, au moins 0,15 requis")},
        {QStringLiteral("el"),
         QStringLiteral("Δεν ήταν δυνατή η πρόσδεση του f1: είναι πολύ μακριά από τον σπόνδυλο· 0 από τα σημεία του βρίσκονται "
                        "εντός 32,3 mm από την επιφάνεια του σπονδύλου (χρειάζονται τουλάχιστον 200). Φέρτε το πιο κοντά στη "
                        "θέση του στον σπόνδυλο (το Εργαλείο Μετακίνησης, ή η θέση του στο σύστημα του σπονδύλου στις "
                        "Ιδιότητες) και κάντε ξανά πρόσδεση."),
         QStringLiteral("σήμα ραβδώσεων 0,04, απαιτείται τουλάχιστον 0,15")},
        {QStringLiteral("en"),
         QStringLiteral("Could not dock f1: it is too far from the drum; 0 of its points lie within 32.3 mm of the drum's "
                        "surface (at least 200 are needed). Bring it nearer its place on the drum (the Move tool, or its "
                        "placement in the drum frame in Properties) and dock again."),
         QStringLiteral("flute signal 0.04, at least 0.15 needed")},
    };
    for (const auto& e : expected) {
        setLanguage(e.code);
        QCOMPARE(widgets::DockJob::errorText(QStringLiteral("f1"), error, far), e.far);
        const QString noFlutes = widgets::DockJob::errorText(QStringLiteral("f1"), error, plain);
        QVERIFY2(noFlutes.contains(e.plain), qPrintable(noFlutes));
        // Another reason: the summary of its code, and the core's detail below.
        const QString other = widgets::DockJob::errorText(QStringLiteral("f1"), error);
        QVERIFY2(other.endsWith(QStringLiteral("\nfragment.poct: the starting pose is too far from the drum")), qPrintable(other));
    }
}

STYLOS_WIDGET_TEST_MAIN(LanguageTextsTest)
#include "LanguageTextsTest.moc"
