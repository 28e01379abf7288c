// Linear sRGB, clamped to [0, 1], to CIE L*a*b* (D65, white Y = 1), as core/color converts:
// shared by the ΔE00 and the ꟻLIP passes.

// CIE 15:2004 companding with the exact rationals (6/29)^3, (29/6)^2 / 3 and 4/29.
float labF(float t) {
    return t > 216.0 / 24389.0 ? pow(t, 1.0 / 3.0) : (841.0 / 108.0) * t + 4.0 / 29.0;
}

// sRGB primaries and the D65 white (0.3127, 0.3290), scaled so that RGB (1,1,1) has Y = 1;
// the constructor takes columns, so each line here is one column of the matrix.
const mat3 kLinearSrgbToXyz = mat3(0.41239079926595951, 0.21263900587151036, 0.019330818715591849,
                                   0.35758433938387796, 0.71516867876775592, 0.11919477979462599,
                                   0.18048078840183429, 0.072192315360733714, 0.95053215224966059);
const vec3 kWhite = vec3(0.9504559270516717, 1.0, 1.0890577507598784);

vec3 linearSrgbToLab(vec3 rgb) {
    vec3 ratio = (kLinearSrgbToXyz * clamp(rgb, 0.0, 1.0)) / kWhite;
    vec3 f = vec3(labF(ratio.x), labF(ratio.y), labF(ratio.z));
    return vec3(116.0 * f.y - 16.0, 500.0 * (f.x - f.y), 200.0 * (f.y - f.z));
}
