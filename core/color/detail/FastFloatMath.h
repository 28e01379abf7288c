#pragma once
// A float math policy with no library calls and no data-dependent branches, so loops over it
// vectorise. Accurate to a few float ulps over the ranges CIEDE2000 needs (tested against
// StdMath in tests/color/FastFloatMathTest.cpp); the polynomial coefficients were fitted for
// this project (minimax on [0, 1] for atan, [-1/2, 1/2] for 2^x); sine and cosine use their
// Taylor series on [-45°, 45°].
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace matevo::formulas {

struct FastFloatMath {
    // Coefficients from the constant term up. 2^x on [-1/2, 1/2]; atan(r) / r in powers of r^2
    // on [0, 1]; sin(r) / r and cos(r) in powers of r^2 (Taylor).
    static constexpr std::array<float, 7> kExp2Coefficients = {1.0f,
                                                               0.69314720670743624f,
                                                               0.24022651505034731f,
                                                               0.055503272201838795f,
                                                               0.0096179945141859347f,
                                                               0.0013400429988540646f,
                                                               0.00015478022809815861f};
    static constexpr std::array<float, 8> kAtanCoefficients = {
        0.9999993355468136f,  -0.3332986064638426f,  0.1994656393694752f, -0.1390862029235393f,
        0.09642171970112862f, -0.05591195847088065f, 0.0218626877435911f, -0.00405448852947783f};
    // (2 / ln 2) / (2k + 1): the atanh series in log2 units.
    static constexpr std::array<float, 5> kLog2AtanhCoefficients = {
        2.8853900817779268f, 0.96179669392597560f, 0.57707801635558536f, 0.41219858311113240f,
        0.32059889797532520f};
    static constexpr std::array<float, 5> kSineCoefficients = {1.0f, -1.0f / 6, 1.0f / 120,
                                                               -1.0f / 5040, 1.0f / 362880};
    static constexpr std::array<float, 6> kCosineCoefficients = {
        1.0f, -1.0f / 2, 1.0f / 24, -1.0f / 720, 1.0f / 40320, -1.0f / 3628800};

    // Horner's rule.
    template <std::size_t N>
    static float polynomial(float x, const std::array<float, N>& coefficients) {
        float result = coefficients[N - 1];
        for (std::size_t i = N - 1; i-- > 0;) result = result * x + coefficients[i];
        return result;
    }

    static float sqrt(float x) { return std::sqrt(x); }

    // For positive normal x.
    static float cbrt(float x) {
        // Thirding the bit pattern thirds the exponent (the constant adds back two thirds of the
        // bias, 127 * 2^23 * 2/3, slightly tuned): a start within a few per cent, which two
        // Halley steps (cubic convergence) take to float precision.
        const auto bits = std::bit_cast<std::int32_t>(x);
        float y = std::bit_cast<float>(std::int32_t(float(bits) * (1.0f / 3.0f)) + 709921077);
        for (int step = 0; step < 2; ++step) {
            const float cube = y * y * y;
            y = y * (cube + 2.0f * x) / (2.0f * cube + x);
        }
        return y;
    }

    // For x <= 0 (results below 2^-125 flush towards 0, far below what ΔE00 can see).
    static float exp(float x) { return exp2(std::max(x, -87.0f) * std::numbers::log2e_v<float>); }

    // For x in [-125, 127]; exact at integers.
    static float exp2(float x) {
        const auto whole = std::int32_t(x + (x < 0.0f ? -0.5f : 0.5f));
        const float fraction = x - float(whole);  // in [-1/2, 1/2]
        return polynomial(fraction, kExp2Coefficients) * std::bit_cast<float>((whole + 127) << 23);
    }

    // For positive normal x; exact at powers of two.
    static float log2(float x) {
        // x = m 2^e with m in [√½, √2): log2 m = (2 / ln 2) atanh(s), s = (m − 1) / (m + 1),
        // |s| < 0.172, whose odd series to s^9 is within 1e-9.
        const auto bits = std::bit_cast<std::int32_t>(x);
        const std::int32_t exponent = (bits - 0x3f3504f3) >> 23;  // 0x3f3504f3: √½
        const float mantissa = std::bit_cast<float>(bits - exponent * (1 << 23));
        const float s = (mantissa - 1.0f) / (mantissa + 1.0f);
        return float(exponent) + s * polynomial(s * s, kLog2AtanhCoefficients);
    }

    // x^y for x > 0 and 0 <= y <= 1; 0 for x = 0. Computed whatever x is (log2 of the
    // smallest normal float stands in for log2 0) and multiplied by 0 or 1 rather than chosen:
    // a choice after this much arithmetic leaves a branch that stops loops from vectorising.
    static float pow(float x, float y) {
        const float power = exp2(y * log2(std::max(x, std::numeric_limits<float>::min())));
        return power * float(x > 0.0f);
    }

    // In [0, 360); 0 for (0, 0).
    static float atan2Degrees(float y, float x) {
        const float ax = std::fabs(x), ay = std::fabs(y);
        const float ratio = std::min(ax, ay) / std::max(std::max(ax, ay), 1e-30f);
        const float atanRatio = ratio * polynomial(ratio * ratio, kAtanCoefficients);
        float degrees = atanRatio * (180.0f / std::numbers::pi_v<float>);
        degrees = ay > ax ? 90.0f - degrees : degrees;
        degrees = x < 0.0f ? 180.0f - degrees : degrees;
        return y < 0.0f ? 360.0f - degrees : degrees;
    }

    // For |degrees| below a few thousand.
    static void sinCosDegrees(float degrees, float& sine, float& cosine) {
        // Reduce to r in [-45°, 45°] and the quadrant q: sin(x) = sin(r + 90° q).
        const auto quadrant =
            std::int32_t(degrees * (1.0f / 90.0f) + (degrees < 0.0f ? -0.5f : 0.5f));
        const float r = (degrees - float(quadrant) * 90.0f) * (std::numbers::pi_v<float> / 180.0f);
        const float r2 = r * r;
        const float sinR = r * polynomial(r2, kSineCoefficients);
        const float cosR = polynomial(r2, kCosineCoefficients);
        const bool swap = (quadrant & 1) != 0;
        const float s = swap ? cosR : sinR;
        const float c = swap ? sinR : cosR;
        sine = (quadrant & 2) != 0 ? -s : s;
        cosine = ((quadrant + 1) & 2) != 0 ? -c : c;
    }
};

}  // namespace matevo::formulas
