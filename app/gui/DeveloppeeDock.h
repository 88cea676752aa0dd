#pragma once
/** @file
 * @brief The Développée dock: the développée panel (widgets::DeveloppeePanel: settings bar, Compute, the
 *        2D view and the fit line) under the 3D view, its settings loaded from and saved to QSettings.
 *        GUI thread only.
 */
#include <QDockWidget>

namespace stylos::widgets {
class DeveloppeePanel;
} // namespace stylos::widgets

namespace stylos::app {

class DeveloppeeDock : public QDockWidget {
    Q_OBJECT

public:
    /** Builds the panel with the settings last saved (QSettings), the brush size with them. */
    explicit DeveloppeeDock(QWidget* parent = nullptr);

    widgets::DeveloppeePanel& panel() const { return *m_panel; }
    /** @brief Keeps the panel's settings and the brush size for the next session. */
    void saveSettings() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    widgets::DeveloppeePanel* m_panel;
};

} // namespace stylos::app
