#pragma once
/** @file
 * @brief The selected fragment's placement typed in its drum's frame, in the Properties dock: θ (degrees about
 *        the drum axis), z (mm along it), r (mm from it) and the two tilts (degrees; lean about the tangent, roll
 *        about the radial direction), read by core::dock::drumFramePose about the drum's first Axis guide
 *        (SceneDocument::drumFor: its assembly's drum, else the docking drum) and the fragment's centre (the
 *        gizmo's: the middle of its octree's bounds). Typing a value moves the fragment (placeInDrumFrame, the
 *        other values kept) as one undo step. Without such a drum, the fields are disabled and a line says why.
 *        GUI thread only.
 */
#include "stylos/widgets/document/SceneDocument.h"

#include <QWidget>

#include <array>
#include <memory>

class QDoubleSpinBox;
class QFormLayout;
class QLabel;

namespace stylos::widgets {

class FragmentBounds;

class DrumFramePoseWidget : public QWidget {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;
    /** The fields, in this order. */
    enum Field { Theta, Z, R, TiltLean, TiltRoll, Spin };
    static constexpr int FieldCount = 6;

    /** @p document is not owned and must outlive the widget. */
    explicit DrumFramePoseWidget(SceneDocument& document, QWidget* parent = nullptr);
    ~DrumFramePoseWidget() override;

    void setFragment(FragmentId id);
    FragmentId fragment() const { return m_id; }
    /** @brief True when the fragment has a drum with an axis guide (the fields are enabled). */
    bool isAvailable() const { return m_available; }

    // For tests.
    QDoubleSpinBox* field(Field field) const { return m_fields[std::size_t(field)]; }
    QLabel* statusLabel() const { return m_status; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refresh();
    void apply(Field field);
    /** The drum frame and the fragment's pose in the drum's file frame; false when there is none. */
    struct Placement;
    bool placement(Placement& out);

    SceneDocument& m_document;
    std::unique_ptr<FragmentBounds> m_bounds;
    QFormLayout* m_form;
    QLabel* m_status;
    std::array<QLabel*, FieldCount> m_labels{};
    std::array<QDoubleSpinBox*, FieldCount> m_fields{};
    FragmentId m_id = core::scene::NoFragment;
    bool m_available = false;
    bool m_updating = false;
};

} // namespace stylos::widgets
