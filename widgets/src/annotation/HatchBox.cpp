#include "annotation/HatchBox.h"

#include <QAbstractItemView>
#include <QStyleOptionComboBox>
#include <QStylePainter>

#include <algorithm>

namespace stylos::widgets {

HatchBox::HatchBox(QWidget* parent) : QComboBox(parent)
{
    setIconSize(QSize(28, 14));
    connect(this, &QComboBox::currentIndexChanged, this, &HatchBox::refreshToolTip);
}

QSize HatchBox::sizeHint() const
{
    QStyleOptionComboBox option;
    initStyleOption(&option);
    const QSize contents(iconSize().width() + 4, std::max(iconSize().height(), fontMetrics().height()));
    return style()->sizeFromContents(QStyle::CT_ComboBox, &option, contents, this);
}

QSize HatchBox::minimumSizeHint() const { return sizeHint(); }

void HatchBox::setDescription(const QString& what)
{
    m_what = what;
    refreshToolTip();
}

void HatchBox::refreshToolTip()
{
    setToolTip(m_what.isEmpty() ? currentText() : QStringLiteral("%1: %2").arg(currentText(), m_what));
    setAccessibleName(currentText());
}

void HatchBox::paintEvent(QPaintEvent*)
{
    QStylePainter painter(this);
    QStyleOptionComboBox option;
    initStyleOption(&option);
    option.currentText.clear(); // the sample alone; the name is in the tooltip and the list
    painter.drawComplexControl(QStyle::CC_ComboBox, option);
    painter.drawControl(QStyle::CE_ComboBoxLabel, option);
}

void HatchBox::showPopup()
{
    // The open list shows the names: as wide as the longest, not as narrow as the closed box.
    const QAbstractItemView* list = view();
    int width = 0;
    for (int i = 0; i < count(); ++i)
        width = std::max(width, fontMetrics().horizontalAdvance(itemText(i)));
    view()->setMinimumWidth(width + iconSize().width() + 4 * list->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 32);
    QComboBox::showPopup();
}

} // namespace stylos::widgets
