#pragma once
/** @file
 * @brief The Properties dock: the selected fragment (FragmentPropertiesWidget: name, visibility, colour,
 *        pose, point and cell counts), its placement in its drum's frame (DrumFramePoseWidget), its contact with the docking drum (ContactReadoutWidget, once
 *        addContactReadout() is called) and the 3D view's display settings (DisplaySettingsWidget), in a
 *        scroll area. GUI thread only.
 */
#include "stylos/core/scene/Fragment.h"

#include <QDockWidget>

class QGroupBox;
class QScrollArea;

namespace stylos::widgets {
class ContactMonitor;
class ContactReadoutWidget;
class DrumFramePoseWidget;
class FragmentPropertiesWidget;
class SceneDocument;
class ViewportWidget;
} // namespace stylos::widgets

namespace stylos::app {

class DisplaySettingsWidget;

class PropertiesDock : public QDockWidget {
    Q_OBJECT

public:
    /** @p viewport may be null (no OpenGL): then there are no display settings. */
    PropertiesDock(widgets::SceneDocument& document, widgets::ViewportWidget* viewport, QWidget* parent = nullptr);

    void setFragment(core::scene::FragmentId id);
    /** @brief Adds the "Contact with the drum" box under the fragment's, showing @p monitor (not owned). */
    void addContactReadout(widgets::ContactMonitor& monitor);
    /** @brief Null before addContactReadout(). */
    widgets::ContactReadoutWidget* contactReadout() const { return m_contact; }
    /** @brief Scrolls the dock so that the contact box shows (after addContactReadout()). */
    void showContactReadout();
    widgets::FragmentPropertiesWidget* fragmentWidget() const { return m_fragment; }
    widgets::DrumFramePoseWidget* drumFrameWidget() const { return m_drumFrame; }
    /** @brief Null without a 3D view. */
    DisplaySettingsWidget* displaySettings() const { return m_display; }

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void retranslateUi();

    QGroupBox* m_fragmentBox;
    QScrollArea* m_scroll;
    QGroupBox* m_displayBox = nullptr;
    QGroupBox* m_contactBox = nullptr;
    QGroupBox* m_drumFrameBox;
    widgets::DrumFramePoseWidget* m_drumFrame;
    widgets::ContactReadoutWidget* m_contact = nullptr;
    widgets::FragmentPropertiesWidget* m_fragment;
    DisplaySettingsWidget* m_display = nullptr;
};

} // namespace stylos::app
