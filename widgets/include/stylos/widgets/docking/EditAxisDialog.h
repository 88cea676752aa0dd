#pragma once
/** @file
 * @brief "Edit axis…": the axis guide of a fragment typed as a point (metres) and a direction (any length, made a
 *        unit vector), in the fragment's own frame. OK with a zero (or not finite) direction is refused: the dialog
 *        stays open and says why. GUI thread only.
 */
#include <Eigen/Core>

#include <QDialog>

#include <array>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;

namespace stylos::widgets {

class EditAxisDialog : public QDialog {
    Q_OBJECT

public:
    EditAxisDialog(const Eigen::Vector3d& point, const Eigen::Vector3d& direction, QWidget* parent = nullptr);

    Eigen::Vector3d point() const;
    /** @brief The direction as typed (accept() refuses a zero one). */
    Eigen::Vector3d direction() const;
    void setPoint(const Eigen::Vector3d& point);
    void setDirection(const Eigen::Vector3d& direction);

    // For tests.
    QLabel* errorLabel() const { return m_error; }
    QDialogButtonBox* buttons() const { return m_buttons; }

public Q_SLOTS:
    void accept() override;

private:
    std::array<QDoubleSpinBox*, 3> m_point{};
    std::array<QDoubleSpinBox*, 3> m_direction{};
    QLabel* m_error;
    QDialogButtonBox* m_buttons;
};

} // namespace stylos::widgets
