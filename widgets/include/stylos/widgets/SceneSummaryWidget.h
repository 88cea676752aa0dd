#pragma once
/** @file
 * @brief Shows a SceneSummaryModel: a table of the loaded files and a label with the total point count.
 */
#include <QWidget>

class QLabel;
class QTableView;

namespace stylos::widgets {

class SceneSummaryModel;

class SceneSummaryWidget : public QWidget {
    Q_OBJECT

public:
    /** Observes @p model (not owned; it must outlive the widget). */
    explicit SceneSummaryWidget(SceneSummaryModel& model, QWidget* parent = nullptr);

    /** The text of the total label, e.g. "Total: 1,234,567 points in 3 files". */
    QString totalText() const;
    QTableView* table() const { return m_table; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void fitColumns();
    void retranslateUi();

    SceneSummaryModel& m_model;
    QTableView* m_table;
    QLabel* m_total;
};

} // namespace stylos::widgets
