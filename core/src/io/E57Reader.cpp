#include "stylos/core/io/E57Reader.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace stylos::core::io {

namespace fs = std::filesystem;

namespace {

/** Records decoded per step: bounds the columns whatever the batch size asked. */
constexpr std::size_t kStepRecords = std::size_t(1) << 16;

/** The scale that maps [lo, hi] onto [0, 1]; a degenerate or unbounded range gives @p fallback. */
std::pair<double, double> rangeOf(std::optional<std::pair<double, double>> limits, double fieldLo, double fieldHi,
                                  std::pair<double, double> fallback)
{
    auto usable = [](double lo, double hi) { return std::isfinite(hi - lo) && hi > lo; };
    if (limits && usable(limits->first, limits->second)) return {limits->first, limits->second - limits->first};
    if (usable(fieldLo, fieldHi)) return {fieldLo, fieldHi - fieldLo};
    return fallback;
}

} // namespace

E57Reader::E57Reader(fs::path path, E57PagedFile file, E57FileHeader header, std::vector<E57Scan> scans,
                     std::vector<ScanPlan> plans, bool scanColumn)
    : PointReader(std::move(path), file.size()),
      m_file(std::move(file)),
      m_fileHeader(header),
      m_scanList(std::move(scans)),
      m_plans(std::move(plans))
{
    m_header.format = "e57-" + std::to_string(header.versionMajor) + "." + std::to_string(header.versionMinor);
    std::uint64_t declared = 0;
    for (const ScanPlan& p : m_plans) declared += m_scanList[p.scan].recordCount;
    m_header.declaredPoints = declared;
    m_header.schema.hasColors = !m_plans.empty() && m_plans.front().color >= 0;
    auto& scalars = m_header.schema.scalarNames;
    if (!m_plans.empty() && m_plans.front().intensity >= 0) {
        m_intensityColumn = int(scalars.size());
        scalars.push_back("intensity");
    }
    if (scanColumn) {
        m_scanColumn = int(scalars.size());
        scalars.push_back(kScanIndexColumn);
    }
    for (const E57Scan& s : m_scanList) m_scans.push_back(s.info);
}

std::string E57Reader::label(std::size_t scan) const
{
    const std::string& name = m_scanList[scan].info.name;
    return "scan " + std::to_string(scan) + (name.empty() ? std::string() : " (\"" + name + "\")");
}

Result<std::unique_ptr<PointReader>> E57Reader::open(const fs::path& path, const ReadOptions& options)
{
    auto file = E57PagedFile::open(path);
    if (!file) return file.error();
    const std::string name = path.string();
    if (file->size() == 0) return Error::at(ErrorCode::Empty, name, "", "the file is empty (0 bytes)");
    if (file->size() < E57PagedFile::PageBytes)
        return Error::at(ErrorCode::Truncated, name, "byte 0",
                         "the file has " + std::to_string(file->size()) + " bytes, less than one 1024-byte page");
    char head[E57FileHeader::Bytes];
    if (auto s = file->read(0, sizeof head, head, "the file header"); !s) return s.error();
    auto header = E57FileHeader::parse(head, file->size(), name);
    if (!header) return header.error();

    const std::string xmlAt = "XML section at byte " + std::to_string(header->xmlOffset);
    constexpr std::uint64_t kMaxXml = std::uint64_t(256) << 20;
    if (header->xmlLength > kMaxXml)
        return Error::at(ErrorCode::Unsupported, name, xmlAt,
                         "an XML section of " + std::to_string(header->xmlLength) + " bytes is beyond the 256 MiB read");
    std::vector<char> xml(static_cast<std::size_t>(header->xmlLength));
    if (auto s = file->read(header->xmlOffset, xml.size(), xml.data(), "the XML section"); !s) return s.error();
    auto scans = parseE57Xml(xml.data(), xml.size(), name, xmlAt);
    if (!scans) return scans.error();
    xml = {};
    if (scans->empty())
        return Error::at(ErrorCode::Empty, name, "", "the file holds no scan (its /data3D list is empty): no points");
    if (options.scan && *options.scan >= scans->size())
        return Error::at(ErrorCode::InvalidArgument, name, "",
                         "scan " + std::to_string(*options.scan) + " does not exist: the file has " +
                             std::to_string(scans->size()) + " scan(s), numbered from 0");

    std::vector<ScanPlan> plans;
    for (std::size_t i = 0; i < scans->size(); ++i) {
        if (options.scan && *options.scan != i) continue;
        const E57Scan& s = (*scans)[i];
        ScanPlan p;
        p.scan = i;
        const int cx = s.field("cartesianX"), cy = s.field("cartesianY"), cz = s.field("cartesianZ");
        const int sr = s.field("sphericalRange"), sa = s.field("sphericalAzimuth"), se = s.field("sphericalElevation");
        int state = -1;
        if (cx >= 0 && cy >= 0 && cz >= 0) {
            p.fields = {cx, cy, cz};
            state = s.field("cartesianInvalidState");
        } else if (sr >= 0 && sa >= 0 && se >= 0) {
            p.spherical = true;
            p.fields = {sr, sa, se};
            state = s.field("sphericalInvalidState");
        } else {
            const std::string scanName = "scan " + std::to_string(i) + (s.info.name.empty() ? "" : " (\"" + s.info.name + "\")");
            return Error::at(ErrorCode::Unsupported, name, xmlAt,
                             scanName + " has neither cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation fields");
        }
        auto addColumn = [&](int field) {
            if (field < 0) return -1;
            p.fields.push_back(field);
            return static_cast<int>(p.fields.size()) - 1;
        };
        p.invalidState = addColumn(state);
        if (const int f = s.field("intensity"); f >= 0) {
            p.intensity = addColumn(f);
            std::optional<std::pair<double, double>> limits;
            if (s.intensityLimits) limits = std::pair{(*s.intensityLimits)[0], (*s.intensityLimits)[1]};
            std::tie(p.intensityMin, p.intensityRange) =
                rangeOf(limits, s.fields[f].valueMinimum(), s.fields[f].valueMaximum(), {0.0, 1.0});
        }
        const int red = s.field("colorRed"), green = s.field("colorGreen"), blue = s.field("colorBlue");
        if (red >= 0 && green >= 0 && blue >= 0) {
            const int channel[3] = {red, green, blue};
            p.color = addColumn(red);
            addColumn(green);
            addColumn(blue);
            for (int k = 0; k < 3; ++k) {
                std::optional<std::pair<double, double>> limits;
                if (s.colorLimits) limits = std::pair{(*s.colorLimits)[2 * k], (*s.colorLimits)[2 * k + 1]};
                const E57Field& f = s.fields[channel[k]];
                std::tie(p.colorMin[k], p.colorRange[k]) =
                    rangeOf(limits, f.valueMinimum(), f.valueMaximum(), {0.0, 255.0});
            }
        }
        plans.push_back(std::move(p));
    }
    // Attributes are kept when every scan read has them.
    const bool allColor = std::all_of(plans.begin(), plans.end(), [](const ScanPlan& p) { return p.color >= 0; });
    const bool allIntensity = std::all_of(plans.begin(), plans.end(), [](const ScanPlan& p) { return p.intensity >= 0; });
    for (ScanPlan& p : plans) {
        if (!allColor) p.color = -1;
        if (!allIntensity) p.intensity = -1;
    }

    const bool scanColumn = plans.size() >= 2;
    std::unique_ptr<E57Reader> reader(
        new E57Reader(path, std::move(file).value(), *header, std::move(scans).value(), std::move(plans), scanColumn));
    // Every scan's section header is checked now, so that a damaged one is refused before any point.
    for (const ScanPlan& p : reader->m_plans) {
        auto vector = E57VectorReader::open(reader->m_file, reader->m_scanList[p.scan], p.fields, reader->label(p.scan));
        if (!vector) return vector.error();
    }
    return std::unique_ptr<PointReader>(std::move(reader));
}

Result<std::size_t> E57Reader::read(PointBatch& batch, std::size_t maxPoints)
{
    assert(maxPoints > 0 && "E57Reader::read(): maxPoints must be positive");
    maxPoints = std::max<std::size_t>(maxPoints, 1);
    batch.reset(m_header.schema, std::min(maxPoints, kStepRecords));
    while (batch.size() < maxPoints && m_current < m_plans.size()) {
        const ScanPlan& plan = m_plans[m_current];
        if (!m_vector) {
            auto vector = E57VectorReader::open(m_file, m_scanList[plan.scan], plan.fields, label(plan.scan));
            if (!vector) return vector.error();
            m_vector.emplace(std::move(vector).value());
        }
        if (m_vector->recordsLeft() == 0) {
            m_vector.reset();
            ++m_current;
            continue;
        }
        auto got = m_vector->read(std::min(maxPoints - batch.size(), kStepRecords), m_columns);
        if (!got) return got.error();
        m_bytesConsumed = std::max(m_bytesConsumed, std::min(m_vector->nextPacket(), m_fileBytes));
        convert(plan, *got, batch);
    }
    if (m_current == m_plans.size()) m_bytesConsumed = m_fileBytes;
    m_pointsRead += batch.size();
    return batch.size();
}

void E57Reader::convert(const ScanPlan& plan, std::size_t n, PointBatch& batch)
{
    const auto& c = m_columns;
    const auto& m = m_scanList[plan.scan].info.pose;
    for (std::size_t i = 0; i < n; ++i) {
        if (plan.invalidState >= 0 && c[plan.invalidState][i] != 0) {
            ++m_pointsMissing;
            continue;
        }
        double x = c[0][i], y = c[1][i], z = c[2][i];
        if (plan.spherical) {
            const double r = x, azimuth = y, elevation = z;
            x = r * std::cos(elevation) * std::cos(azimuth);
            y = r * std::cos(elevation) * std::sin(azimuth);
            z = r * std::sin(elevation);
        }
        const double px = m[0] * x + m[1] * y + m[2] * z + m[3];
        const double py = m[4] * x + m[5] * y + m[6] * z + m[7];
        const double pz = m[8] * x + m[9] * y + m[10] * z + m[11];
        if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(pz)) {
            ++m_pointsSkipped;
            continue;
        }
        batch.positions.insert(batch.positions.end(), {px, py, pz});
        if (plan.color >= 0)
            for (int k = 0; k < 3; ++k) {
                const double v = (c[plan.color + k][i] - plan.colorMin[k]) / plan.colorRange[k] * 255.0;
                batch.colors.push_back(static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)));
            }
        if (plan.intensity >= 0)
            batch.scalars[m_intensityColumn].push_back((c[plan.intensity][i] - plan.intensityMin) / plan.intensityRange);
        if (m_scanColumn >= 0) batch.scalars[m_scanColumn].push_back(double(plan.scan));
    }
}

} // namespace stylos::core::io
