#include "stylos/widgets/SceneSummaryModel.h"

#include <QFileInfo>
#include <QLocale>

namespace stylos::widgets {

namespace {

QString formatSize(const ScanSummary& scan)
{
    if (!scan.hasBounds()) return QStringLiteral("—");
    const auto s = scan.size();
    const QLocale locale;
    return QStringLiteral("%1 × %2 × %3").arg(locale.toString(s[0], 'f', 3), locale.toString(s[1], 'f', 3),
                                             locale.toString(s[2], 'f', 3));
}

QString formatBounds(const ScanSummary& scan)
{
    if (!scan.hasBounds()) return {};
    const auto& b = scan.bounds;
    return SceneSummaryModel::tr("min (%1, %2, %3)\nmax (%4, %5, %6)")
        .arg(b[0], 0, 'f', 4).arg(b[1], 0, 'f', 4).arg(b[2], 0, 'f', 4)
        .arg(b[3], 0, 'f', 4).arg(b[4], 0, 'f', 4).arg(b[5], 0, 'f', 4);
}

} // namespace

SceneSummaryModel::SceneSummaryModel(QObject* parent) : QAbstractTableModel(parent) {}

int SceneSummaryModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_scans.size());
}

int SceneSummaryModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SceneSummaryModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const ScanSummary& scan = m_scans[static_cast<std::size_t>(index.row())];
    if (role == Qt::ToolTipRole) return index.column() == SizeColumn ? formatBounds(scan) : scan.path;
    if (role == Qt::TextAlignmentRole && (index.column() == PointsColumn || index.column() == SkippedColumn))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    const QLocale locale;
    switch (index.column()) {
    case FileColumn: return QFileInfo(scan.path).fileName();
    case FormatColumn: return scan.format;
    case PointsColumn: return locale.toString(static_cast<qulonglong>(scan.points));
    case SkippedColumn: return locale.toString(static_cast<qulonglong>(scan.skipped));
    case SizeColumn: return formatSize(scan);
    case AttributesColumn: return scan.attributes.isEmpty() ? tr("none") : scan.attributes.join(QStringLiteral(", "));
    default: return {};
    }
}

QVariant SceneSummaryModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case FileColumn: return tr("File");
    case FormatColumn: return tr("Format");
    case PointsColumn: return tr("Points");
    case SkippedColumn: return tr("Skipped");
    case SizeColumn: return tr("Size (x × y × z)");
    case AttributesColumn: return tr("Attributes");
    default: return {};
    }
}

void SceneSummaryModel::addScan(const ScanSummary& summary)
{
    for (std::size_t i = 0; i < m_scans.size(); ++i) {
        if (m_scans[i].path == summary.path) {
            m_scans[i] = summary;
            const int row = static_cast<int>(i);
            Q_EMIT dataChanged(index(row, 0), index(row, ColumnCount - 1));
            updateTotal();
            return;
        }
    }
    const int row = rowCount();
    beginInsertRows({}, row, row);
    m_scans.push_back(summary);
    endInsertRows();
    updateTotal();
}

void SceneSummaryModel::clear()
{
    beginResetModel();
    m_scans.clear();
    endResetModel();
    updateTotal();
}

void SceneSummaryModel::updateTotal()
{
    std::uint64_t total = 0;
    for (const ScanSummary& scan : m_scans) total += scan.points;
    m_totalPoints = total;
    Q_EMIT totalPointsChanged(total);
}

} // namespace stylos::widgets
