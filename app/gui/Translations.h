#pragma once
/** @file
 * @brief The workbench's language: the system's by default (French, Greek, else English), or the one
 *        chosen in Help › Language, kept in QSettings ("ui/language": "", "en", "fr" or "el"). Switching
 *        replaces the installed translators; every widget then gets a LanguageChange event and
 *        retranslates itself. The Stylos catalogues are embedded under :/i18n; Qt's own (standard
 *        dialogs) come from the Qt installation when present. GUI thread only.
 */
#include <QObject>
#include <QString>
#include <QStringList>

class QTranslator;

namespace stylos::app {

class Translations : public QObject {
    Q_OBJECT

public:
    explicit Translations(QObject* parent = nullptr);

    /** @brief The languages offered, as codes: "en", "fr", "el". */
    static QStringList languages();
    /** @brief The language's own name: "English", "Français", "Ελληνικά". */
    static QString nativeName(const QString& code);

    /** @brief The saved choice ("" = follow the system). */
    static QString savedLanguage();

    /** @brief Installs @p code ("" = the system's) and saves the choice. False when its catalogue is missing. */
    bool setLanguage(const QString& code);
    /** @brief The choice in effect ("" = the system's). */
    QString language() const { return m_language; }
    /** @brief The code actually loaded ("en" when the system's language is not offered). */
    QString loadedLanguage() const { return m_loaded; }

private:
    QTranslator* m_stylos = nullptr;
    QTranslator* m_qt = nullptr;
    QString m_language;
    QString m_loaded;
};

} // namespace stylos::app
