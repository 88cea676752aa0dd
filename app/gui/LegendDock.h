#pragma once
/** @file
 * @brief The Legend dock: the project's annotation legend (widgets::LegendWidget — both layers' classes with
 *        colour, name, hatch, cells and area; choosing the class to paint; rename, recolour, hatch, add,
 *        delete, each one undo step). GUI thread only.
 */
#include <QDockWidget>

namespace stylos::widgets {
class ClassMeasures;
class LegendWidget;
class SceneDocument;
} // namespace stylos::widgets

namespace stylos::app {

class LegendDock : public QDockWidget {
    Q_OBJECT

public:
    /** @p measures may be null; neither owned. */
    LegendDock(widgets::SceneDocument& document, widgets::ClassMeasures* measures, QWidget* parent = nullptr);

    widgets::LegendWidget& legend() const { return *m_legend; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    widgets::LegendWidget* m_legend;
};

} // namespace stylos::app
