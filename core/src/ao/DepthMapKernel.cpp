// The DepthMap method of the 3D skydome: per direction, a shadow map of the cells (see DepthMapFrame.h
// for the projection).
//
// Pass 1 (splat): a cell's cube, seen along d, covers a hexagon H (the projection of the unit cube); every
// pixel whose centre lies in H keeps the farthest cell toward the sky (the largest key c·d) with the
// offset of that cell's centre from the pixel centre. A pixel therefore holds the last cell that the line
// through its centre (along d) enters — what a ray cast there would meet — and a closed shell of cells
// leaves no pixel centre uncovered behind it. H is at most 2 pixels wide on each axis (half-width ≤ √3/2),
// so the candidates are the 2 × 2 pixels around the centre, each kept by three slab tests.
// Pass 2 (test): a cell reads the pixel under its centre. The stored key and offset give the occluder's
// centre relative to the cell's, Δ = (key difference)·d + (offset across d); both centres lie on the
// integer lattice and the estimate is within 0.1 of it, so rounding gives Δ exactly, and the occluder
// rule of AmbientOcclusion.h applies exactly to that cell: hidden iff it lies ahead (key difference > 0)
// and Δ·n > bias. The cell's own entry (Δ = 0) never hides it, a flat floor never shadows itself, and the
// line through the pixel centre is at most 0.71 cell from the cell's own ray. Visibility is binary; the
// cells' opacity is not used (every cell occludes, as in ReferenceAo).
//
// Why this footprint and this test (mean absolute difference from ReferenceAo, 256 directions, on a
// generated drum at octree level 9, 0.95 M cells; a closed box and a sphere of cells seen from inside):
//   hexagon, exact Δ (this file)                    0.023 (+0.022 lighter)   box 0.012   sphere 0.017
//   nearest pixel only, exact Δ                     0.036 (light leaks)      box 0.024   sphere 0.046
//   all 2 × 2 pixels, exact Δ                       0.020 (−0.004)           box 0.060   sphere 0.057 (too dark)
//   hexagon, Δ from the 1/8-cell offset unrounded   0.06–0.11 on the voxel drums of AoDepthMapTest (too
//                                                   dark: neighbours exactly `bias` above flip at random)
//   hexagon, keys only (key_j > key_i + bias / n·d) 0.087 at level 8 (too dark), tilted planes 0.03–0.07
// The hexagon with the exact Δ gives planes and convex shells exactly the reference's values and the best
// correlation everywhere (0.99 on the drum).
//
// Cost per cell·direction: two blocked, auto-vectorised loops (projection, slab tests, packing; then
// decoding and the test) around two scalar loops (4 max-updates; 1 read), compiled for AVX-512, AVX2
// and plain x86-64 (DepthMapPasses.cpp); pass 2 skips the blocks whose normals all face away, except
// two-sided (the probe directions of AoOptions::twoSided, AmbientOcclusion.cpp), where every block runs and
// each direction adds to the side of the receiver's tangent plane it lies on. The cells
// come in breadth-first (Morton) order, so consecutive cells touch neighbouring pixels. Scratch per
// worker: the map, W × H int32 over the projection of the cells' box (about twice the number of surface
// cells for a closed object), cleared per direction, the blocks' normal cones and 64-cell block arrays.
#include "AoKernel.h"
#include "DepthMapFrame.h"
#include "DepthMapPasses.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace stylos::core::ao::detail {
namespace {

class DepthMapKernel final : public DirectionKernel {
public:
    DepthMapKernel(const PreparedCells& cells, const PreparedCells* receivers, const AoOptions& options,
                   const DepthMapPasses& passes)
        : m_cells(cells), m_receivers(receivers ? *receivers : cells), m_offLattice(receivers != nullptr),
          m_twoSided(receivers != nullptr && twoSidedApplies(options)),
          m_bias(float(receivers ? options.receiverBias : options.bias)), m_cosine(options.cosineWeighted), m_passes(passes),
          m_scratch(std::make_unique<DepthMapScratch>())
    {
        // The cells' own box (not the grid's from 0): the map covers only its projection.
        const std::vector<float>* axes[3] = {&cells.x, &cells.y, &cells.z};
        for (int a = 0; a < 3; ++a) {
            const auto [lo, hi] = std::minmax_element(axes[a]->begin(), axes[a]->end());
            m_lo[std::size_t(a)] = lo == axes[a]->end() ? 0.0f : *lo;
            m_hi[std::size_t(a)] = hi == axes[a]->end() ? 0.0f : *hi;
        }
        makeNormalCones();
    }

    void run(const std::array<float, 3>& d, Accumulator& sums) override
    {
        if (m_cells.size() == 0) return;
        const DepthMapFrame f = makeDepthMapFrame(d, m_lo, m_hi);
        m_map.assign(std::size_t(f.width) * std::size_t(f.height), 0);
        m_passes.splat(f, m_cells, m_map.data(), *m_scratch);
        for (std::size_t b = 0; b < m_cones.size(); ++b) {
            const Cone& c = m_cones[b];
            m_facing[b] = c.axis[0] * d[0] + c.axis[1] * d[1] + c.axis[2] * d[2] >= -c.sine - 1e-4;
        }
        if (m_twoSided) {
            m_passes.testTwoSided(f, m_receivers, m_map.data(), m_facing.data(), m_bias, m_cosine, sums, *m_scratch);
            return;
        }
        (m_offLattice ? m_passes.testOffLattice : m_passes.test)(f, m_receivers, m_map.data(), m_facing.data(), m_bias,
                                                                 m_cosine, sums, *m_scratch);
    }

private:
    /**
     * Per block of the passes, the cone of its normals: unit axis and the sine of its half-angle (2 when
     * the half-angle reaches 90°). No normal of the block faces d when axis·d < −sine: the block then adds
     * nothing in pass 2 and is skipped. Breadth-first order keeps a block's cells together on the
     * surface, so for most directions about half the blocks face away.
     */
    struct Cone {
        double axis[3] = {0, 0, 0};
        double sine = 2;
    };

    void makeNormalCones()
    {
        constexpr std::size_t kBlock = DepthMapScratch::kBlock;
        const PreparedCells& r = m_receivers;
        const std::size_t n = r.size();
        m_cones.resize((n + kBlock - 1) / kBlock);
        m_facing.resize(m_cones.size());
        for (std::size_t b = 0; b < m_cones.size(); ++b) {
            const std::size_t first = b * kBlock, last = std::min(n, first + kBlock);
            double m[3] = {0, 0, 0};
            for (std::size_t i = first; i < last; ++i) {
                m[0] += r.nx[i];
                m[1] += r.ny[i];
                m[2] += r.nz[i];
            }
            const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            if (!(length > 1e-9)) continue;
            double cosine = 1.0; // the smallest cosine between the axis and a normal of the block
            for (std::size_t i = first; i < last; ++i) {
                const double nx = r.nx[i], ny = r.ny[i], nz = r.nz[i];
                const double norm = std::sqrt(nx * nx + ny * ny + nz * nz);
                cosine = norm > 0.0 ? std::min(cosine, (nx * m[0] + ny * m[1] + nz * m[2]) / (length * norm)) : cosine;
            }
            if (!(cosine > 0.0)) continue;
            Cone& c = m_cones[b];
            for (int a = 0; a < 3; ++a)
                c.axis[a] = m[a] / length;
            c.sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
        }
    }

    const PreparedCells& m_cells;     ///< the occluders (pass 1)
    const PreparedCells& m_receivers; ///< pass 2: the cells themselves, or receivers off their lattice
    const bool m_offLattice;
    const bool m_twoSided;
    const float m_bias;
    const bool m_cosine;
    const DepthMapPasses m_passes;
    std::unique_ptr<DepthMapScratch> m_scratch;
    std::array<float, 3> m_lo{}, m_hi{}; ///< the cells' centres' box, cell edges
    std::vector<std::int32_t> m_map;     ///< per pixel: (key << 8) | offset, 0 = empty
    std::vector<Cone> m_cones;
    std::vector<std::uint8_t> m_facing; ///< per block, this direction: some normal faces it
};

} // namespace

Result<const DepthMapPasses*> chosenDepthMapPasses()
{
    static const std::vector<DepthMapPasses> variants = depthMapPassVariants(); // the fastest first
    const char* named = std::getenv("STYLOS_AO_PASSES"); // once: the kernels get what this returns
    if (named == nullptr || *named == '\0') return &variants.front();
    const std::string name = named;
    std::string names;
    for (const DepthMapPasses& v : variants) {
        if (name == v.isa) return &v;
        names += std::string(names.empty() ? "" : ", ") + v.isa;
    }
    std::string problem = "'";
    problem += name;
    problem += "' is not one of the passes this processor runs (" + names + ")";
    return Error::at(ErrorCode::InvalidArgument, "STYLOS_AO_PASSES", "", problem);
}

std::unique_ptr<DirectionKernel> makeDepthMapKernel(const PreparedCells& cells, const AoOptions& options,
                                                    const DepthMapPasses& passes, const PreparedCells* receivers)
{
    return std::make_unique<DepthMapKernel>(cells, receivers, options, passes);
}

} // namespace stylos::core::ao::detail
