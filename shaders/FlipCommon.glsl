// What the two ꟻLIP passes share (core/gpu/FlipPass.h): their settings, the layout of the
// filter taps and of the row-filtered planes. Mirrors core/color/FlipStages.h.

layout(push_constant) uniform Settings {
    int width;
    int height;
    uint referenceImage;  // index of the reference in its binding
    uint firstCandidate;  // index of the first candidate in its binding
    int csfRadius;        // contrast-sensitivity taps: 2 csfRadius + 1 per filter
    int featureRadius;    // feature-detector taps: 2 featureRadius + 1 per filter
    float maxColorDistance;  // c_max: the Hunt-adjusted HyAB distance green-blue, ^ q_c
} settings;

// The largest filter radius the passes take (FlipRowFilter.comp's shared tile is sized by it):
// the contrast-sensitivity radius at 1000 pixels per degree, the most FlipSettings allows.
// Mirrored by kMaxFlipFilterRadius in core/gpu/FlipPass.cpp.
const int kMaxFilterRadius = 136;

// The taps, one filter after another: the contrast-sensitivity filters (achromatic,
// red-green, the two blue-yellow terms), then the feature detectors (Gaussian, its first and
// second derivative). Rows and columns use the same taps.
// A uniform buffer, not a storage buffer: every invocation reads the same tap, and lavapipe
// loads a uniform-buffer value at a uniform offset once for all lanes, where a storage-buffer
// read is a gather per lane.
const int kMaxTapVectors = (7 * (2 * kMaxFilterRadius + 1) + 3) / 4;
layout(std140, binding = 2) uniform Taps { vec4 tapVectors[kMaxTapVectors]; };
float tapAt(int index) { return tapVectors[index >> 2][index & 3]; }
const int kAchromaticTaps = 0, kRedGreenTaps = 1, kBlueYellowTaps0 = 2, kBlueYellowTaps1 = 3;
const int kGaussianTaps = 0, kFirstDerivativeTaps = 1, kSecondDerivativeTaps = 2;

float csfTap(int which, int offset) {
    return tapAt(which * (2 * settings.csfRadius + 1) + offset + settings.csfRadius);
}
float featureTap(int which, int offset) {
    int featureStart = 4 * (2 * settings.csfRadius + 1);
    return tapAt(featureStart + which * (2 * settings.featureRadius + 1) + offset +
                 settings.featureRadius);
}

// The row pass's output: per image (slot 0 the reference, slot 1 + i candidate i) seven
// planes, each filtered along x only: the opponent channels through their contrast-sensitivity
// filters, and the normalised achromatic channel through the feature detectors.
const uint kPlanes = 7;
const uint kAchromaticPlane = 0, kRedGreenPlane = 1, kBlueYellowPlane0 = 2,
           kBlueYellowPlane1 = 3, kSlopePlane = 4, kCurvaturePlane = 5, kBlurredPlane = 6;

uint planeIndex(uint slot, uint plane, uint pixel) {
    uint pixelCount = uint(settings.width * settings.height);
    return (slot * kPlanes + plane) * pixelCount + pixel;
}
