// A panel's picture at print resolution: resampling a développée, tinting by class.
#include "stylos/core/plate/PanelImage.h"

#include <algorithm>
#include <cmath>

namespace stylos::core::plate {

namespace {

std::uint16_t toSample(double value)
{
    return std::uint16_t(std::lround(std::clamp(value, 0.0, 1.0) * 65535.0));
}

} // namespace

PanelImage resampleField(const GreyField& source, double sourceColumns, bool periodic, int width, int height)
{
    PanelImage out;
    out.width = width;
    out.height = height;
    out.channels = 1;
    out.samples.assign(std::size_t(width) * std::size_t(height), 65535);
    const bool hasClasses = !source.classes.empty();
    if (hasClasses) out.classes.assign(out.samples.size(), 0);
    if (source.width <= 0 || source.height <= 0 || width <= 0 || height <= 0) return out;
    const double sx = sourceColumns / double(width), sy = double(source.height) / double(height);
    auto column = [&](long c) -> long {
        if (periodic) {
            const long w = source.width;
            // Wrap within the period (the last column may be partial); fall back to clamping at the edges.
            c = ((c % w) + w) % w;
            return c;
        }
        return std::clamp<long>(c, 0, source.width - 1);
    };
    for (int y = 0; y < height; ++y) {
        const double fy = (double(y) + 0.5) * sy - 0.5;
        const long y0 = long(std::floor(fy));
        const double ty = fy - double(y0);
        const long ya = std::clamp<long>(y0, 0, source.height - 1), yb = std::clamp<long>(y0 + 1, 0, source.height - 1);
        for (int x = 0; x < width; ++x) {
            const double fx = (double(x) + 0.5) * sx - 0.5;
            const long x0 = long(std::floor(fx));
            const double tx = fx - double(x0);
            const long xa = column(x0), xb = column(x0 + 1);
            double sum = 0, weight = 0;
            const long xs[2] = {xa, xb}, ys[2] = {ya, yb};
            const double wx[2] = {1 - tx, tx}, wy[2] = {1 - ty, ty};
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    const std::size_t k = std::size_t(ys[j]) * std::size_t(source.width) + std::size_t(xs[i]);
                    const double w = wx[i] * wy[j];
                    if (w <= 0 || !source.coverage[k]) continue;
                    sum += w * double(source.values[k]);
                    weight += w;
                }
            const std::size_t o = std::size_t(y) * std::size_t(width) + std::size_t(x);
            // The nearest source pixel decides whether there is surface here (no halo of half-covered pixels).
            const long nx = column(long(std::floor((double(x) + 0.5) * sx)));
            const long ny = std::clamp<long>(long(std::floor((double(y) + 0.5) * sy)), 0, source.height - 1);
            const std::size_t nearest = std::size_t(ny) * std::size_t(source.width) + std::size_t(nx);
            if (source.coverage[nearest] && weight > 0) out.samples[o] = toSample(sum / weight);
            if (hasClasses && source.coverage[nearest]) out.classes[o] = source.classes[nearest];
        }
    }
    return out;
}

void tintByClass(PanelImage& image, const annotation::Legend& legend, annotation::AnnotationLayer layer)
{
    constexpr double a = 0.65;
    std::vector<std::uint16_t> rgb(std::size_t(image.width) * std::size_t(image.height) * 3);
    std::array<std::array<double, 3>, 256> factor;
    for (auto& f : factor) f = {1.0, 1.0, 1.0};
    for (const annotation::LegendClass& c : legend.classes(layer))
        factor[c.id] = {1 - a + a * c.colour.r / 255.0, 1 - a + a * c.colour.g / 255.0, 1 - a + a * c.colour.b / 255.0};
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        const std::uint8_t id = image.classes.empty() ? 0 : image.classes[p];
        for (int c = 0; c < 3; ++c) {
            const std::uint16_t g = image.channels == 1 ? image.samples[p] : image.samples[p * 3 + std::size_t(c)];
            rgb[p * 3 + std::size_t(c)] = std::uint16_t(std::lround(double(g) * factor[id][std::size_t(c)]));
        }
    }
    image.samples = std::move(rgb);
    image.channels = 3;
}

std::array<bool, 256> shownClasses(const PanelImage& image, int block)
{
    std::array<bool, 256> shown{};
    const int w = image.width, h = image.height;
    if (w <= 0 || h <= 0 || image.classes.size() != std::size_t(w) * std::size_t(h)) return shown;
    block = std::max(1, block);
    // Each block's class: the one that fills more than half of its pixels (a block cut by the image's edge: of those).
    const int bw = (w + block - 1) / block, bh = (h + block - 1) / block;
    std::vector<std::uint8_t> blocks(std::size_t(bw) * std::size_t(bh), 0);
    std::array<int, 256> counts{};
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const int x0 = bx * block, y0 = by * block, x1 = std::min(w, x0 + block), y1 = std::min(h, y0 + block);
            counts.fill(0);
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) ++counts[image.classes[std::size_t(y) * std::size_t(w) + std::size_t(x)]];
            const int half = (x1 - x0) * (y1 - y0) / 2;
            for (int c = 1; c < 256; ++c)
                if (counts[std::size_t(c)] > half) blocks[std::size_t(by) * std::size_t(bw) + std::size_t(bx)] = std::uint8_t(c);
        }
    const auto at = [&](int x, int y) { return blocks[std::size_t(y) * std::size_t(bw) + std::size_t(x)]; };
    for (int y = 1; y + 1 < bh; ++y)
        for (int x = 1; x + 1 < bw; ++x) {
            const std::uint8_t c = at(x, y);
            if (c != 0 && !shown[c] && at(x - 1, y) == c && at(x + 1, y) == c && at(x, y - 1) == c && at(x, y + 1) == c)
                shown[c] = true;
        }
    return shown;
}

} // namespace stylos::core::plate
