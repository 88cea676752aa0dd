#include "stylos/widgets/SceneSummaryWidget.h"

#include "stylos/widgets/SceneSummaryModel.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableView>
#include <QVBoxLayout>

namespace stylos::widgets {

SceneSummaryWidget::SceneSummaryWidget(SceneSummaryModel& model, QWidget* parent)
    : QWidget(parent), m_model(model), m_table(new QTableView(this)), m_total(new QLabel(this))
{
    setObjectName(QStringLiteral("SceneSummaryWidget"));
    m_table->setObjectName(QStringLiteral("sceneSummaryTable"));
    m_total->setObjectName(QStringLiteral("totalPointsLabel"));

    m_table->setModel(&m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);

    QFont font = m_total->font();
    font.setPointSizeF(font.pointSizeF() * 1.4);
    font.setBold(true);
    m_total->setFont(font);
    m_total->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_total);
    layout->addWidget(m_table, 1);

    connect(&m_model, &SceneSummaryModel::totalPointsChanged, this, &SceneSummaryWidget::retranslateUi);
    connect(&m_model, &QAbstractItemModel::modelReset, this, &SceneSummaryWidget::retranslateUi);
    // Columns fit their contents as files arrive; the user may still resize them.
    connect(&m_model, &QAbstractItemModel::rowsInserted, this, &SceneSummaryWidget::fitColumns);
    connect(&m_model, &QAbstractItemModel::dataChanged, this, &SceneSummaryWidget::fitColumns);
    retranslateUi();
    fitColumns();
}

QString SceneSummaryWidget::totalText() const
{
    return m_total->text();
}

void SceneSummaryWidget::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
        fitColumns();
    }
}

void SceneSummaryWidget::fitColumns()
{
    // Every column but the last, which stretches to the table's edge.
    for (int column = 0; column + 1 < m_model.columnCount(); ++column) m_table->resizeColumnToContents(column);
}

void SceneSummaryWidget::retranslateUi()
{
    const int files = m_model.rowCount();
    if (files == 0) {
        m_total->setText(tr("No scan loaded"));
        return;
    }
    const QString points = QLocale().toString(static_cast<qulonglong>(m_model.totalPoints()));
    m_total->setText(tr("Total: %1 points in %n file(s)", nullptr, files).arg(points));
}

} // namespace stylos::widgets
