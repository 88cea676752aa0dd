#pragma once
/** @file
 * @brief The Log dock: what the workbench did and what went wrong, one timestamped line per event
 *        (imports, projects opened and saved, tasks finished, every error with the file it names).
 *        Errors also go to stderr, so automation sees them. Keeps the last 5000 lines. GUI thread only.
 */
#include <QDockWidget>

class QPlainTextEdit;

namespace stylos::app {

class LogDock : public QDockWidget {
    Q_OBJECT

public:
    enum class Level { Info, Error };

    explicit LogDock(QWidget* parent = nullptr);

    /** @brief Appends "[hh:mm:ss] message" (an error in red, and on stderr). */
    void append(Level level, const QString& message);
    /** @brief The log as plain text (for tests). */
    QString text() const;
    /** @brief Lines appended at Level::Error since the start. */
    int errorCount() const { return m_errors; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    QPlainTextEdit* m_text;
    int m_errors = 0;
};

} // namespace stylos::app
