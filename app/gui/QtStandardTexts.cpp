// The texts of Qt's standard dialog buttons (QDialogButtonBox, QMessageBox), listed here so that lupdate puts
// them in our translations: Qt asks for them in the context "QPlatformTheme", and Debian ships no Qt translation
// for Greek (nor any unless qt6-translations-l10n is installed), so without these a French or Greek dialog
// showed "Cancel" and "OK". Our translator answers when Qt's own has no text (Translations.cpp installs Qt's last,
// so it is asked first).
#include <QtGlobal>

namespace stylos::app {

/** The English texts, as Qt 6 writes them (QPlatformTheme::defaultStandardButtonText). */
[[maybe_unused]] const char* const kQtStandardButtonTexts[] = {
    QT_TRANSLATE_NOOP("QPlatformTheme", "OK"),        QT_TRANSLATE_NOOP("QPlatformTheme", "Save"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Save All"),  QT_TRANSLATE_NOOP("QPlatformTheme", "Open"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&Yes"),      QT_TRANSLATE_NOOP("QPlatformTheme", "Yes to &All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&No"),       QT_TRANSLATE_NOOP("QPlatformTheme", "N&o to All"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Abort"),     QT_TRANSLATE_NOOP("QPlatformTheme", "Retry"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Ignore"),    QT_TRANSLATE_NOOP("QPlatformTheme", "Close"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Cancel"),    QT_TRANSLATE_NOOP("QPlatformTheme", "Discard"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Help"),      QT_TRANSLATE_NOOP("QPlatformTheme", "Apply"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Reset"),     QT_TRANSLATE_NOOP("QPlatformTheme", "Restore Defaults"),
};

} // namespace stylos::app
