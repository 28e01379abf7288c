// CIEDE2000 (kL = kC = kH = 1) between two L*a*b* colours, as core/color computes it, and the
// heatmap's colour-map entry of a difference: shared by the ΔE00 pass and the sphere render,
// which compares each candidate with the target as it shades it.

// sqrt(C^7 / (C^7 + 25^7)), the chroma weight of G and R_C; x^7 by multiplication (pow() on
// lavapipe costs a log and an exp per lane).
float chromaWeight(float chroma) {
    float square = chroma * chroma;
    float seventh = square * square * square * chroma;
    return sqrt(seventh / (seventh + 6103515625.0));  // 25^7
}

// T = 1 - 0.17 cos(h - 30°) + 0.24 cos 2h + 0.32 cos(3h + 6°) - 0.20 cos(4h - 63°), from
// cos h and sin h by the multiple-angle identities.
float hueWeight(float c1, float s1) {
    float c2 = 2.0 * c1 * c1 - 1.0;
    float s2 = 2.0 * s1 * c1;
    float c3 = c1 * (2.0 * c2 - 1.0);  // cos 3h = cos h (2 cos 2h - 1)
    float s3 = s1 * (2.0 * c2 + 1.0);  // sin 3h = sin h (2 cos 2h + 1)
    float c4 = 2.0 * c2 * c2 - 1.0;
    float s4 = 2.0 * s2 * c2;
    const float cos30 = 0.86602540378, sin30 = 0.5;
    const float cos6 = 0.99452189537, sin6 = 0.10452846327;
    const float cos63 = 0.45399049974, sin63 = 0.89100652419;
    return 1.0 - 0.17 * (c1 * cos30 + s1 * sin30) + 0.24 * c2 +
           0.32 * (c3 * cos6 - s3 * sin6) - 0.20 * (c4 * cos63 + s4 * sin63);
}

// The unit vector of hue angle h' (a', b') / C'; zero for a neutral colour, whose hue the
// formula takes as 0 and which then counts for nothing in the means and differences.
vec2 hueDirection(vec2 aPrimeB, float chroma) {
    return chroma > 0.0 ? aPrimeB / chroma : vec2(0.0);
}

// CIEDE2000 as Sharma et al. (2005) define it, with the hue angles kept as unit vectors:
// inverse tangents, sines and cosines are long polynomials per lane on lavapipe. With u1, u2
// the hue directions, the short-way hue difference Δh' has 2 sin(Δh'/2) = ±|u2 - u1| (the
// chord; its sign that of the turn from u1 to u2), and the mean hue h̄' (the mid-angle the
// short way round, or the chromatic colour's hue when the other is neutral) is the direction
// of u1 + u2. Only the rotation term needs h̄' as an angle.
float ciede2000(vec3 lab1, vec3 lab2) {
    float c1 = length(lab1.yz);
    float c2 = length(lab2.yz);
    float g = 0.5 * (1.0 - chromaWeight(0.5 * (c1 + c2)));
    vec2 ab1 = vec2((1.0 + g) * lab1.y, lab1.z);
    vec2 ab2 = vec2((1.0 + g) * lab2.y, lab2.z);
    float cp1 = length(ab1);
    float cp2 = length(ab2);
    vec2 u1 = hueDirection(ab1, cp1);
    vec2 u2 = hueDirection(ab2, cp2);

    float dL = lab2.x - lab1.x;
    float dC = cp2 - cp1;
    float turn = u1.x * u2.y - u1.y * u2.x;  // sin Δh'
    float dH = sqrt(cp1 * cp2) * (turn < 0.0 ? -length(u2 - u1) : length(u2 - u1));

    // Opposite hues have no short way: the formula then takes the lower hue (the one in
    // [0°, 180°)) plus 90°; two neutral colours have hue 0.
    vec2 bisector = u1 + u2;
    if (dot(bisector, bisector) < 1e-12) {
        vec2 lower = u1.y > 0.0 || (u1.y == 0.0 && u1.x > 0.0) ? u1 : u2;
        bisector = cp1 * cp2 != 0.0 ? vec2(-lower.y, lower.x) : vec2(1.0, 0.0);
    }
    vec2 meanHue = normalize(bisector);  // (cos h̄', sin h̄')
    float hMean = degrees(atan(meanHue.y, meanHue.x));
    if (hMean < 0.0) hMean += 360.0;

    float lMean = 0.5 * (lab1.x + lab2.x);
    float cMean = 0.5 * (cp1 + cp2);
    float t = hueWeight(meanHue.x, meanHue.y);
    float hueOffset = (hMean - 275.0) / 25.0;
    float dTheta = 30.0 * exp(-hueOffset * hueOffset);
    float rC = 2.0 * chromaWeight(cMean);
    float lShift = (lMean - 50.0) * (lMean - 50.0);
    float sL = 1.0 + 0.015 * lShift / sqrt(20.0 + lShift);
    float sC = 1.0 + 0.045 * cMean;
    float sH = 1.0 + 0.015 * cMean * t;
    float rT = -sin(radians(2.0 * dTheta)) * rC;
    float termL = dL / sL;
    float termC = dC / sC;
    float termH = dH / sH;
    return sqrt(max(termL * termL + termC * termC + termH * termH + rT * termC * termH, 0.0));
}
