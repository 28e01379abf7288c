#include "ScreenshotAnalysis.h"

#include <algorithm>
#include <cmath>

#include "color/Srgb.h"

namespace matevo::testing {

Screenshot::Screenshot(const Image& linear)
    : width_(linear.width), height_(linear.height), rgb_(linear.pixelCount() * 3) {
    for (std::size_t i = 0; i < linear.pixelCount(); ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            const double value = std::clamp(double(linear.rgba[i * 4 + c]), 0.0, 1.0);
            rgb_[i * 3 + c] = std::uint8_t(std::lround(linearToSrgb(value) * 255.0));
        }
}

bool Screenshot::lit(int x, int y, int threshold) const {
    const std::uint8_t* p = pixel(x, y);
    return std::max({p[0], p[1], p[2]}) > threshold;
}

std::vector<Blob> Screenshot::litBlobs(const PixelRect& area, int minPixels, int threshold) const {
    std::vector<Blob> blobs;
    std::vector<std::uint8_t> seen(std::size_t(width_) * std::size_t(height_), 0);
    std::vector<std::pair<int, int>> stack;
    for (int y = area.y0; y < area.y1; ++y) {
        for (int x = area.x0; x < area.x1; ++x) {
            const std::size_t index = std::size_t(y) * std::size_t(width_) + std::size_t(x);
            if (seen[index] || !lit(x, y, threshold)) continue;
            Blob blob;
            blob.bounds = {x, y, x + 1, y + 1};
            double sums[3] = {0, 0, 0};
            stack.assign(1, {x, y});
            seen[index] = 1;
            while (!stack.empty()) {
                const auto [px, py] = stack.back();
                stack.pop_back();
                ++blob.pixels;
                for (int c = 0; c < 3; ++c) sums[c] += pixel(px, py)[c];
                blob.bounds = {std::min(blob.bounds.x0, px), std::min(blob.bounds.y0, py),
                               std::max(blob.bounds.x1, px + 1), std::max(blob.bounds.y1, py + 1)};
                const int neighbours[4][2] = {
                    {px + 1, py}, {px - 1, py}, {px, py + 1}, {px, py - 1}};
                for (const auto& n : neighbours) {
                    if (n[0] < area.x0 || n[0] >= area.x1 || n[1] < area.y0 || n[1] >= area.y1)
                        continue;
                    const std::size_t next =
                        std::size_t(n[1]) * std::size_t(width_) + std::size_t(n[0]);
                    if (seen[next] || !lit(n[0], n[1], threshold)) continue;
                    seen[next] = 1;
                    stack.push_back({n[0], n[1]});
                }
            }
            if (blob.pixels < minPixels) continue;
            for (int c = 0; c < 3; ++c) blob.meanRgb[c] = sums[c] / blob.pixels;
            blobs.push_back(blob);
        }
    }
    return blobs;
}

int Screenshot::saturatedPixels(const PixelRect& area) const {
    int count = 0;
    for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x) {
            const std::uint8_t* p = pixel(x, y);
            const int high = std::max({p[0], p[1], p[2]});
            const int low = std::min({p[0], p[1], p[2]});
            count += high > 60 && high - low > 0.45 * high;
        }
    return count;
}

}  // namespace matevo::testing
