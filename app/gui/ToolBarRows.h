#pragma once
/** @file
 * @brief Two toolbars on one row while they fit the window's width, on two rows when they do not (a narrow
 *        window, a long language): every button stays visible and readable, none behind the » extension.
 *        Watches the window's width and the toolbars' own size (a tool's options shown or hidden, a new language).
 */
#include <QObject>

class QMainWindow;
class QToolBar;

namespace stylos::app {

class ToolBarRows : public QObject {
    Q_OBJECT

public:
    /** @p first and @p second are in @p window's top area, in this order. */
    ToolBarRows(QMainWindow& window, QToolBar& first, QToolBar& second);

    /** @brief Whether @p second is on a row of its own now. */
    bool isSplit() const;
    /** @brief Puts the break in or takes it out for the current widths (also done on its own, a turn later). */
    void update();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void schedule();

    QMainWindow& m_window;
    QToolBar& m_first;
    QToolBar& m_second;
    bool m_scheduled = false;
};

} // namespace stylos::app
