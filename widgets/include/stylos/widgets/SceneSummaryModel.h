#pragma once
/** @file
 * @brief The list of loaded files as a table model: file, format, points, skipped points, size and
 *        attributes, with the total point count. Lives on the GUI thread; filled from SceneLoader's signals.
 */
#include "stylos/widgets/ScanSummary.h"

#include <QAbstractTableModel>

#include <cstdint>
#include <vector>

namespace stylos::widgets {

class SceneSummaryModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { FileColumn, FormatColumn, PointsColumn, SkippedColumn, SizeColumn, AttributesColumn, ColumnCount };

    explicit SceneSummaryModel(QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    const ScanSummary& scan(int row) const { return m_scans.at(static_cast<std::size_t>(row)); }
    /** Sum of the points of every loaded file. */
    std::uint64_t totalPoints() const { return m_totalPoints; }

public Q_SLOTS:
    /** Appends @p summary, or replaces the row of a file with the same path. */
    void addScan(const stylos::widgets::ScanSummary& summary);
    void clear();

Q_SIGNALS:
    void totalPointsChanged(quint64 total);

private:
    void updateTotal();

    std::vector<ScanSummary> m_scans;
    std::uint64_t m_totalPoints = 0;
};

} // namespace stylos::widgets
