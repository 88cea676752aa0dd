#include "stylos/widgets/docking/EditAxisDialog.h"

#include "stylos/widgets/util/NumberSpinBox.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>

#include <cmath>

namespace stylos::widgets {

namespace {

QWidget* row(QWidget* parent, std::array<QDoubleSpinBox*, 3>& spins, const QString& name, int decimals, const QString& suffix)
{
    auto* box = new QWidget(parent);
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    for (int k = 0; k < 3; ++k) {
        auto* spin = new NumberSpinBox(box);
        spin->setObjectName(QStringLiteral("%1%2").arg(name).arg(k));
        spin->setRange(-1e7, 1e7);
        spin->setDecimals(decimals);
        spin->setSuffix(suffix);
        spins[std::size_t(k)] = spin;
        layout->addWidget(spin);
    }
    return box;
}

} // namespace

EditAxisDialog::EditAxisDialog(const Eigen::Vector3d& point, const Eigen::Vector3d& direction, QWidget* parent)
    : QDialog(parent), m_error(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("editAxisDialog"));
    setWindowTitle(tr("Edit axis"));
    auto* form = new QFormLayout(this);
    auto* note = new QLabel(tr("The axis guide in the fragment's own frame: a point on it and its direction."), this);
    note->setWordWrap(true);
    form->addRow(note);
    form->addRow(tr("Point (x, y, z):"), row(this, m_point, QStringLiteral("axisPoint"), 4, QStringLiteral(" m")));
    form->addRow(tr("Direction (x, y, z):"), row(this, m_direction, QStringLiteral("axisDirection"), 6, QString()));
    m_error->setObjectName(QStringLiteral("axisError"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #c0392b;"));
    form->addRow(m_error);
    form->addRow(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &EditAxisDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &EditAxisDialog::reject);
    setPoint(point);
    setDirection(direction);
}

Eigen::Vector3d EditAxisDialog::point() const { return {m_point[0]->value(), m_point[1]->value(), m_point[2]->value()}; }

Eigen::Vector3d EditAxisDialog::direction() const
{
    return {m_direction[0]->value(), m_direction[1]->value(), m_direction[2]->value()};
}

void EditAxisDialog::setPoint(const Eigen::Vector3d& point)
{
    for (int k = 0; k < 3; ++k) m_point[std::size_t(k)]->setValue(point[k]);
}

void EditAxisDialog::setDirection(const Eigen::Vector3d& direction)
{
    for (int k = 0; k < 3; ++k) m_direction[std::size_t(k)]->setValue(direction[k]);
}

void EditAxisDialog::accept()
{
    const double length = direction().norm();
    if (!(std::isfinite(length) && length > 1e-9)) {
        m_error->setText(tr("The direction of the axis cannot be zero: give at least one non-zero component "
                            "(for a vertical axis: 0, 0, 1)."));
        return;
    }
    m_error->clear();
    QDialog::accept();
}

} // namespace stylos::widgets
