#pragma once
/** @file
 * @brief The display settings of the 3D view, shown in the Properties dock: shading (headlight, skydome,
 *        scan colour, eye-dome lighting, annotation) and the annotation layer the Annotation shading tints by
 *        (material or tool mark: announced, the owner hands it to AnnotationSync), splat size, point budget (millions of points while the view refines), and level of
 *        detail — view-dependent under the budget, or the paper's global level slider —, and whether the gaps
 *        between splats are filled on screen (ViewportWidget::setGapFilling, on by default). Applied to the view
 *        at once and kept in QSettings (group "view"). GUI thread only.
 */
#include <QWidget>

#include <array>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSlider;

namespace stylos::widgets {
class ViewportWidget;
}

namespace stylos::app {

class DisplaySettingsWidget : public QWidget {
    Q_OBJECT

public:
    /** Drives @p viewport (not owned; it must outlive the widget). Restores the saved settings into it. */
    explicit DisplaySettingsWidget(widgets::ViewportWidget& viewport, QWidget* parent = nullptr);

    QComboBox* shadingBox() const { return m_shading; }
    QDoubleSpinBox* splatSpin() const { return m_splat; }
    QDoubleSpinBox* budgetSpin() const { return m_budget; }
    QComboBox* detailBox() const { return m_detail; }
    QComboBox* annotationLayerBox() const { return m_layer; }
    /** @brief Shows @p layer (an AnnotationLayer as int) without announcing it. */
    void setAnnotationLayer(int layer);
    QSlider* levelSlider() const { return m_level; }
    QCheckBox* gapFillBox() const { return m_gapFill; }
    /** @brief The label of row @p row (0 shading, 1 annotation layer … 5 level, 6 gap filling), for tests. */
    QLabel* label(int row) const { return m_labels.at(static_cast<std::size_t>(row)); }

    /** @brief Shows the view's current shading (after a menu changed it). */
    void syncFromViewport();

Q_SIGNALS:
    /** @brief The user chose the annotation layer @p layer (an AnnotationLayer as int). */
    void annotationLayerChanged(int layer);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void apply();
    void save() const;

    widgets::ViewportWidget& m_viewport;
    QFormLayout* m_form;
    QComboBox* m_shading;
    QComboBox* m_layer;
    QDoubleSpinBox* m_splat;
    QDoubleSpinBox* m_budget;
    QComboBox* m_detail;
    QSlider* m_level;
    QLabel* m_levelValue;
    QCheckBox* m_gapFill;
    std::array<QLabel*, 7> m_labels{};
    bool m_updating = false;
};

} // namespace stylos::app
