#pragma once
/** @file
 * @brief The Properties dock's contents for one fragment: its name, visibility and colour, its pose as a
 *        translation (metres) and three rotation angles (degrees, Rz·Ry·Rx, see core::scene::Pose), its size
 *        (the extent of its leaves along its own axes) and what its octree holds (points, leaf and total cells,
 *        depth, file). Every edit goes through the
 *        document's undo stack; the fields follow the document (undo, other views). GUI thread only.
 */
#include "stylos/core/scene/Fragment.h"

#include <QWidget>

#include <array>
#include <memory>

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace stylos::widgets {

class FragmentBounds;
class SceneDocument;

class FragmentPropertiesWidget : public QWidget {
    Q_OBJECT

public:
    /** Edits fragments of @p document (not owned; it must outlive the widget). */
    explicit FragmentPropertiesWidget(SceneDocument& document, QWidget* parent = nullptr);
    ~FragmentPropertiesWidget() override;

    /** @brief Shows fragment @p id (NoFragment: nothing, every field disabled). */
    void setFragment(core::scene::FragmentId id);
    core::scene::FragmentId fragment() const { return m_id; }

    // The fields, for tests and for the lead's layout.
    QLineEdit* nameEdit() const { return m_name; }
    QCheckBox* visibleCheck() const { return m_visible; }
    QPushButton* colourButton() const { return m_colour; }
    /** @brief Translation x, y, z in metres (0..2) and rotation about x, y, z in degrees (3..5). */
    QDoubleSpinBox* poseSpin(int i) const { return m_pose[static_cast<std::size_t>(i)]; }
    /** @brief "x × y × z" of the leaves' extent in the fragment's own frame (mm; m from 10 m). */
    QLabel* sizeLabel() const { return m_size; }
    QLabel* pointsLabel() const { return m_points; }
    QLabel* leafCellsLabel() const { return m_leafCells; }
    QLabel* totalCellsLabel() const { return m_totalCells; }
    QLabel* depthLabel() const { return m_depth; }
    QLabel* importedLabel() const { return m_imported; }
    QLabel* fileLabel() const { return m_file; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refresh();
    void applyName();
    void applyPose(int component);
    void chooseColour();

    static constexpr std::size_t RowCount = 16;

    SceneDocument& m_document;
    core::scene::FragmentId m_id = core::scene::NoFragment;
    bool m_updating = false;
    QFormLayout* m_form;
    QLineEdit* m_name;
    QCheckBox* m_visible;
    QPushButton* m_colour;
    std::array<QDoubleSpinBox*, 6> m_pose{};
    QLabel* m_size;
    QLabel* m_points;
    QLabel* m_leafCells;
    QLabel* m_totalCells;
    QLabel* m_depth;
    QLabel* m_imported;  ///< the import frame: up axis, unit (and offset)
    QLabel* m_file;
    std::array<QLabel*, RowCount> m_labels{};  ///< the form's row labels
    std::unique_ptr<FragmentBounds> m_centres; ///< coarse bounds: the centre a typed rotation turns about
    std::unique_ptr<FragmentBounds> m_leaves;  ///< the leaves' bounds: the size shown
};

} // namespace stylos::widgets
