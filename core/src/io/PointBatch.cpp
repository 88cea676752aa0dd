#include "stylos/core/io/PointBatch.h"

namespace stylos::core::io {

std::vector<std::string> PointSchema::attributeNames() const
{
    std::vector<std::string> names;
    if (hasNormals) names.emplace_back("normal");
    if (hasColors) names.emplace_back("color");
    names.insert(names.end(), scalarNames.begin(), scalarNames.end());
    return names;
}

void PointBatch::reset(const PointSchema& schema, std::size_t capacity)
{
    positions.clear();
    positions.reserve(3 * capacity);
    normals.clear();
    colors.clear();
    if (schema.hasNormals) normals.reserve(3 * capacity);
    if (schema.hasColors) colors.reserve(3 * capacity);
    scalars.resize(schema.scalarNames.size());
    for (auto& column : scalars) {
        column.clear();
        column.reserve(capacity);
    }
}

void PointBatch::append(const PointBatch& other)
{
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    colors.insert(colors.end(), other.colors.begin(), other.colors.end());
    if (scalars.size() < other.scalars.size()) scalars.resize(other.scalars.size());
    for (std::size_t s = 0; s < other.scalars.size(); ++s)
        scalars[s].insert(scalars[s].end(), other.scalars[s].begin(), other.scalars[s].end());
}

void PointBatch::popBack()
{
    if (positions.empty()) return;
    const std::size_t n = size() - 1;
    positions.resize(3 * n);
    if (normals.size() > 3 * n) normals.resize(3 * n);
    if (colors.size() > 3 * n) colors.resize(3 * n);
    for (auto& column : scalars)
        if (column.size() > n) column.resize(n);
}

} // namespace stylos::core::io
