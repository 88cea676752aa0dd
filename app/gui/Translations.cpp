#include "Translations.h"

#include <QCoreApplication>
#include <QApplication>
#include <QWidget>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace stylos::app {

namespace {
const auto LanguageKey = QStringLiteral("ui/language");
}

Translations::Translations(QObject* parent) : QObject(parent) {}

QStringList Translations::languages()
{
    return {QStringLiteral("en"), QStringLiteral("fr"), QStringLiteral("el")};
}

QString Translations::nativeName(const QString& code)
{
    if (code == QLatin1String("fr")) return QStringLiteral("Français");
    if (code == QLatin1String("el")) return QStringLiteral("Ελληνικά");
    return QStringLiteral("English");
}

QString Translations::savedLanguage()
{
    const QString code = QSettings().value(LanguageKey).toString();
    return languages().contains(code) ? code : QString();
}

bool Translations::setLanguage(const QString& code)
{
    // The system's, not QLocale(): that is the default this function sets below (the last language chosen).
    const QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
    QString loaded = locale.language() == QLocale::French ? QStringLiteral("fr")
                     : locale.language() == QLocale::Greek ? QStringLiteral("el")
                                                           : QStringLiteral("en");
    auto* stylos = new QTranslator(this);
    // An installed copy (share/stylos/translations beside bin/, which a translator may update) comes first,
    // then the one embedded in the program.
    const QString installed =
        QCoreApplication::applicationDirPath() + QStringLiteral("/../share/stylos/translations");
    if (!stylos->load(QStringLiteral("stylos_") + loaded, installed) &&
        !stylos->load(QStringLiteral(":/i18n/stylos_") + loaded)) {
        delete stylos;
        return false;
    }
    auto* qt = new QTranslator(this);
    if (!qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                  QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        delete qt;
        qt = nullptr;
    }
    for (QTranslator* old : {m_stylos, m_qt}) {
        if (!old) continue;
        QCoreApplication::removeTranslator(old);
        old->deleteLater();
    }
    m_stylos = stylos;
    m_qt = qt;
    QCoreApplication::installTranslator(m_stylos);
    if (m_qt) QCoreApplication::installTranslator(m_qt);
    // Numbers follow the chosen language too (decimal comma and grouping in French and Greek), the system's when
    // none is chosen; widgets read QLocale() when they retranslate.
    const QLocale numbers = code.isEmpty() ? QLocale::system() : QLocale(code);
    QLocale::setDefault(numbers);
    // Widgets made before keep the locale they were made with unless told: number fields would go on writing
    // the old decimal point. Each window passes it to its children (a LocaleChange event each).
    for (QWidget* window : QApplication::topLevelWidgets()) window->setLocale(numbers);
    m_language = code;
    m_loaded = loaded;
    QSettings().setValue(LanguageKey, code);
    return true;
}

} // namespace stylos::app
