// libFuzzer harness: opening a packed octree (octree/PoctLayout.cpp, PackedOctree.cpp, PoctChildIndex.cpp)
// and using it as the workbench does: every cell of every level, a view-dependent cut (ViewCut.cpp) from a
// camera outside the box, a click (CellPick.cpp), the leaf spacing and the attribute layers. The section and
// header checksums (XXH64) are recomputed first so that mutations reach the checks behind them (the checksum
// check itself is covered by PackedOctreeTest). A file that opens must then be safe to walk.
#include "FuzzSupport.h"

#include "stylos/core/octree/CellPick.h"
#include "stylos/core/octree/PackedOctree.h"
#include "stylos/core/octree/ViewCut.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos::core;
    const std::vector<std::uint8_t> bytes = stylos::fuzz::withPoctChecksums(data, size);
    auto opened = octree::PackedOctree::open(stylos::fuzz::writeScratch(bytes.data(), bytes.size(), "poct"));
    if (!opened) return 0;
    const octree::PackedOctree& tree = opened.value();

    std::uint64_t seen = 0;
    for (int level = 0; level <= tree.depth(); ++level) {
        std::uint64_t inLevel = 0;
        tree.forEachCell(level, [&](const octree::CellView& cell) {
            if (cell.index != inLevel) stylos::fuzz::broken("forEachCell() skipped or repeated a cell");
            ++inLevel;
            return true;
        });
        if (inLevel != tree.cellCount(level)) stylos::fuzz::broken("forEachCell() did not visit every cell");
        seen += inLevel;
    }
    if (seen != tree.totalCells()) stylos::fuzz::broken("the levels do not add up to totalCells()");

    const octree::RootBox& box = tree.box();
    const std::array<double, 3> centre{box.origin[0] + box.size / 2, box.origin[1] + box.size / 2,
                                       box.origin[2] + box.size / 2};
    octree::CutCamera camera;
    camera.eye = {centre[0], centre[1] - 3 * box.size, centre[2]};
    camera.cullToFrustum = false;
    octree::CutOptions options;
    options.pointBudget = 4096;
    const octree::CutResult cut = octree::computeViewCut(tree, camera, options);
    if (cut.cells.size() > options.pointBudget) stylos::fuzz::broken("the cut exceeds its budget");

    (void)octree::nearestCell(tree, centre, box.size);
    (void)octree::pickRay(tree, camera.eye, {0.0, 1.0, 0.0}, 0.0, 0.01);
    if (tree.cellCount(tree.depth()) > 0) (void)tree.leafSpacing(0);
    for (const octree::AttributeView& layer : tree.attributes())
        if (layer.bytes.empty() && tree.cellCount(tree.depth()) > 0) stylos::fuzz::broken("an empty attribute layer");
    return 0;
}
