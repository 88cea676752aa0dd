#pragma once
/** @file
 * @brief The painting bar of the Développée dock: the tool (Navigate N, Brush B, Eraser E, Polygon / lasso L,
 *        Magic wand W, Fill holes H — the same keys work in the view), the layer and the class painted (with
 *        their legend colours; kept in step with the Legend dock through DeveloppeeAnnotator), the brush size
 *        in mm on the object, the wand's criterion (height or shading) and tolerance (mm or % of the grey
 *        range), and the overlay's opacity. It only sets the view and the annotator. GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"

#include <QWidget>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace stylos::widgets {

class DeveloppeeAnnotator;
class DeveloppeeView;
class SceneDocument;

class PaintToolBar : public QWidget {
    Q_OBJECT

public:
    /** None owned; all must outlive the bar. */
    PaintToolBar(const SceneDocument& document, DeveloppeeAnnotator& annotator, DeveloppeeView& view,
                 QWidget* parent = nullptr);

    void retranslateUi();

protected:
    void changeEvent(QEvent* event) override;

private:
    void fillClasses();
    void showActive();
    void applyTolerance();
    void updateEnabled();

    const SceneDocument& m_document;
    DeveloppeeAnnotator& m_annotator;
    DeveloppeeView& m_view;
    QButtonGroup* m_tools;
    QComboBox* m_layer;
    QComboBox* m_class;
    QLabel* m_sizeLabel;
    QDoubleSpinBox* m_size;
    QComboBox* m_criterion;
    QDoubleSpinBox* m_tolerance;
    QLabel* m_opacityLabel;
    QSlider* m_opacity;
    double m_heightTolerance = 1.0; ///< mm
    double m_shadeTolerance = 5.0;  ///< % of the grey range
    bool m_updating = false;
    core::annotation::AnnotationLayer m_listedLayer = core::annotation::AnnotationLayer::Material;
};

} // namespace stylos::widgets
