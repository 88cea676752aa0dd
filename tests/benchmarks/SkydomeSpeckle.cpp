// stylos_skydome_speckle DRUM.ply [CROP_PREFIX]: the skydome développée of a generated drum, raw heights against
// the default smoothing (shading/HeightNoise.h), judged where the geometry is known: the fillets (flat strips
// at the outer radius between the flutes) must read evenly, the flute bottoms darker.
//
// Fillets and flute bottoms are found from the heights, not from the shading under test: the median height of
// each column over the middle rows gives the flute profile across the drum (its noise averaged over ~700
// pixels); columns within 0.3 mm of the top of that profile, and whose ±4 neighbours are too, are fillet cores,
// columns within 1 mm of its bottom are flute bottoms. Pixels more than 1 mm off their column's median (the
// broken region, the claw band) are left out. Prints, for each variant, the standard deviation of the
// displayed (1–99 % stretched) values over the fillet cores, their mean and that of the flute bottoms; with
// CROP_PREFIX, writes PREFIX-raw.png and PREFIX-smoothed.png, the same 800 × 400 crop of both.
#include "stylos/core/cloud/LoadPointCloud.h"
#include "stylos/core/developpee/Developpee.h"
#include "stylos/core/image/ImageWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace stylos::core;

namespace {

struct Classes {
    std::vector<std::uint8_t> kind; // 0 other, 1 fillet core, 2 flute bottom
};

Classes classify(const shading::HeightField& f)
{
    const int w = f.width(), h = f.height();
    const int r0 = h / 10, r1 = h * 8 / 10;
    std::vector<float> profile(std::size_t(w), 0.0f);
    std::vector<float> column;
    for (int c = 0; c < w; ++c) {
        column.clear();
        for (int r = r0; r < r1; ++r)
            if (f.hasHeight(c, r)) column.push_back(f.heightAt(c, r));
        if (column.empty()) continue;
        std::nth_element(column.begin(), column.begin() + std::ptrdiff_t(column.size() / 2), column.end());
        profile[std::size_t(c)] = column[column.size() / 2];
    }
    std::vector<float> sorted = profile;
    std::sort(sorted.begin(), sorted.end());
    const float top = sorted[sorted.size() * 99 / 100], bottom = sorted[sorted.size() / 100];
    std::vector<std::uint8_t> columnKind(std::size_t(w), 0);
    for (int c = 0; c < w; ++c) {
        const float p = profile[std::size_t(c)];
        if (p > top - 0.0003f) columnKind[std::size_t(c)] = 1;
        else if (p < bottom + 0.001f) columnKind[std::size_t(c)] = 2;
    }
    Classes out;
    out.kind.assign(std::size_t(w) * std::size_t(h), 0);
    for (int c = 4; c + 4 < w; ++c) {
        std::uint8_t k = columnKind[std::size_t(c)];
        if (k == 1)
            for (int d = -4; d <= 4; ++d) k = columnKind[std::size_t(c + d)] == 1 ? k : 0;
        if (k == 0) continue;
        for (int r = r0; r < r1; ++r)
            if (f.stateAt(c, r) == shading::PixelState::Measured &&
                std::abs(f.heightAt(c, r) - profile[std::size_t(c)]) < 0.001f)
                out.kind[f.index(c, r)] = k;
    }
    return out;
}

struct Figures {
    double filletStd = 0, filletMean = 0, fluteMean = 0;
    std::size_t fillets = 0, flutes = 0;
};

Figures measure(const shading::ShadedImage& s, const Classes& k)
{
    Figures f;
    double sum2 = 0;
    for (std::size_t i = 0; i < k.kind.size(); ++i) {
        if (k.kind[i] == 1) f.filletMean += s.values[i], sum2 += double(s.values[i]) * s.values[i], ++f.fillets;
        else if (k.kind[i] == 2) f.fluteMean += s.values[i], ++f.flutes;
    }
    f.filletMean /= double(std::max<std::size_t>(1, f.fillets));
    f.fluteMean /= double(std::max<std::size_t>(1, f.flutes));
    f.filletStd = std::sqrt(std::max(0.0, sum2 / double(std::max<std::size_t>(1, f.fillets)) - f.filletMean * f.filletMean));
    return f;
}

shading::ShadedImage crop(const shading::ShadedImage& s, int c0, int r0, int w, int h)
{
    shading::ShadedImage out;
    out.width = std::min(w, s.width - c0);
    out.height = std::min(h, s.height - r0);
    out.pixelSize = s.pixelSize;
    for (int r = r0; r < r0 + out.height; ++r)
        for (int c = c0; c < c0 + out.width; ++c) {
            out.values.push_back(s.value(c, r));
            out.coverage.push_back(s.covered(c, r) ? 1 : 0);
        }
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: stylos_skydome_speckle DRUM.ply [CROP_PREFIX]\n");
        return 2;
    }
    auto cloud = cloud::loadPointCloud(argv[1]);
    if (!cloud) {
        std::fprintf(stderr, "%s\n", cloud.error().message.c_str());
        return 1;
    }
    developpee::DeveloppeeOptions options;
    options.smoothing = 0.0;
    auto raw = developpee::computeDeveloppee(*cloud, options);
    if (!raw) {
        std::fprintf(stderr, "%s\n", raw.error().message.c_str());
        return 1;
    }
    const Classes classes = classify(raw->field);
    options.smoothing.reset();
    auto smoothed = developpee::computeDeveloppee(*cloud, options);
    if (!smoothed) return 1;
    std::printf("%d x %d pixels of %.3f mm, height noise %.3f mm\n", raw->field.width(), raw->field.height(),
                raw->unroll.pixelSize * 1e3, smoothed->heightNoise * 1e3);
    for (const auto* d : {&*raw, &*smoothed}) {
        const Figures f = measure(d->shaded, classes);
        std::printf("smoothing %.3f mm: fillet cores %zu px, std %.4f, mean %.3f; flute bottoms %zu px, mean %.3f; "
                    "fillets - flutes %.3f; shading %.2f s\n",
                    d->smoothing * 1e3, f.fillets, f.filletStd, f.filletMean, f.flutes, f.fluteMean,
                    f.filletMean - f.fluteMean, d->timings.shading);
    }
    if (argc > 2) {
        const int c0 = raw->field.width() / 3, r0 = raw->field.height() / 2;
        const std::string prefix = argv[2];
        (void)image::writeShadedImage(crop(raw->shaded, c0, r0, 800, 400), prefix + "-raw.png");
        (void)image::writeShadedImage(crop(smoothed->shaded, c0, r0, 800, 400), prefix + "-smoothed.png");
    }
    return 0;
}
