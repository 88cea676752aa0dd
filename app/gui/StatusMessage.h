#pragma once
/** @file
 * @brief The status bar's message: the first line of the last report, cut with "…" to the width the status bar
 *        gives it (never clipped mid-letter, never widening the window), the whole text as its tooltip; cleared
 *        after a timeout. The log and the docks keep the whole text too. GUI thread only.
 */
#include <QLabel>

class QTimer;

namespace stylos::app {

class StatusMessage : public QLabel {
    Q_OBJECT

public:
    explicit StatusMessage(QWidget* parent = nullptr);

    /** @brief Shows @p message (its first line) for @p timeoutMs ms (0: until the next one). */
    void showMessage(const QString& message, int timeoutMs = 0);
    void clearMessage();
    /** @brief Shows @p tip (a menu's or a button's status tip) over the message while it is not empty; an empty
     *         tip brings the message back. Cut with "…" as the message is (QStatusBar cut it without one). */
    void setTip(const QString& tip);
    QString tip() const { return m_tip; }
    /** @brief The whole message shown now (the tooltip's text); empty once cleared. */
    QString message() const { return m_message; }
    /** @brief Whether the label shows less than the message's first line (it ends in "…"). */
    bool isElided() const;

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void refresh();

    QString m_message;
    QString m_tip;
    QTimer* m_timer;
};

} // namespace stylos::app
