// What the two ꟻLIP passes share (core/gpu/FlipPass.h): their settings, the filter radii and
// taps, the layout of the row-filtered planes. Mirrors core/color/FlipStages.h.

layout(push_constant) uniform Settings {
    int width;
    int height;
    uint referenceImage;  // index of the reference in its binding
    uint firstCandidate;  // index of the first candidate in its binding
    float maxColorDistance;  // c_max: the Hunt-adjusted HyAB distance green-blue, ^ q_c
} settings;

// The filter radii of the viewing condition, fixed when the pipeline is made (FlipPass makes
// one per viewing condition): every filter loop then has a known length and is unrolled, so
// each tap is read at a constant offset, once for all invocations, and the pixels a pass
// filters stay in registers. (lavapipe turns every storage-buffer or shared-memory read at an
// offset that varies per invocation into a loop over the SIMD lanes, one per component, and
// every uniform-buffer read at a loop-dependent offset into a gather: those reads, not the
// arithmetic, were the cost. So the passes read images and planes as texel buffers, which it
// fetches for all lanes at once, one whole texel per lane.)
layout(constant_id = 0) const int kCsfRadius = 10;     // taps: 2 kCsfRadius + 1 per filter
layout(constant_id = 1) const int kFeatureRadius = 9;  // taps: 2 kFeatureRadius + 1 per filter
const int kRadius = kCsfRadius > kFeatureRadius ? kCsfRadius : kFeatureRadius;

// The widest filters the passes take (FlipPass refuses wider ones: about 148 pixels per
// degree), and the most taps the uniform block holds. Mirrored by kMaxFlipFilterRadius in
// core/gpu/FlipPass.cpp.
const int kMaxFilterRadius = 20;

// The taps, one filter after another: the contrast-sensitivity filters (achromatic,
// red-green, the two blue-yellow terms), then the feature detectors (Gaussian, its first and
// second derivative). Rows and columns use the same taps. Each filter is even or odd
// (core/color/FlipStages.cpp), so the passes add (or subtract) mirrored pixels first and
// multiply once per pair, as the CPU reference does.
const int kMaxTapVectors = (7 * (2 * kMaxFilterRadius + 1) + 3) / 4;
layout(std140, binding = 2) uniform Taps { vec4 tapVectors[kMaxTapVectors]; };
float tapAt(int index) { return tapVectors[index >> 2][index & 3]; }
const int kAchromaticTaps = 0, kRedGreenTaps = 1, kBlueYellowTaps0 = 2, kBlueYellowTaps1 = 3;
const int kGaussianTaps = 0, kFirstDerivativeTaps = 1, kSecondDerivativeTaps = 2;

float csfTap(int which, int offset) {
    return tapAt(which * (2 * kCsfRadius + 1) + offset + kCsfRadius);
}
vec4 csfTaps(int offset) {
    return vec4(csfTap(kAchromaticTaps, offset), csfTap(kRedGreenTaps, offset),
                csfTap(kBlueYellowTaps0, offset), csfTap(kBlueYellowTaps1, offset));
}
float featureTap(int which, int offset) {
    const int featureStart = 4 * (2 * kCsfRadius + 1);
    return tapAt(featureStart + which * (2 * kFeatureRadius + 1) + offset + kFeatureRadius);
}

// Each invocation of either pass filters a run of kRun pixels (a row segment, a column
// segment), kBlock at a time: a loop over the run's blocks (not unrolled), each block's
// kBlock outputs unrolled. A window of kBlock + 2 kRadius pixels slides along the run: each
// block loads its kBlock new pixels once and keeps the 2 kRadius before them from the last
// block, so a pixel is loaded once per run it reaches, not once per output it reaches
// ((kRun + 2 kRadius) / kRun loads per output). Only the block is unrolled, which keeps
// lavapipe's compile time (paid at the first dispatch, on the queue) a fraction of an
// unrolled run's; FlipPass sets both (docs/flip.md has the trade-off).
layout(constant_id = 2) const int kRun = 32;
layout(constant_id = 3) const int kBlock = 4;
const int kWindow = kBlock + 2 * kRadius;

// The row pass's output: per image (slot 0 the reference, slot 1 + i candidate i) and pixel,
// two vec4 filtered along x only. The first: the opponent channels through their
// contrast-sensitivity filters (achromatic, red-green, the two blue-yellow terms); the
// second: the normalised achromatic channel through the feature detectors (first and second
// derivative, Gaussian) and, in w, the pixel's own alpha (the pooling needs it). The row pass
// writes both vec4 of a pixel as one u64vec4 at planePixel, the combination reads vec4 texels
// at planeIndex.
uint planePixel(uint slot, uint pixel) {
    return slot * uint(settings.width * settings.height) + pixel;
}
uint planeIndex(uint slot, uint pixel, uint which) { return 2 * planePixel(slot, pixel) + which; }
