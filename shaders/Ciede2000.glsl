// CIEDE2000 (kL = kC = kH = 1) between two L*a*b* colours, as core/color computes it, and the
// heatmap's colour-map entry of a difference: shared by the ΔE00 pass and the sphere render,
// which compares each candidate with the target as it shades it.

// Hue angle in degrees in [0, 360); 0 for a neutral colour, as in Sharma et al. (2005).
float hueDegrees(float b, float aPrime) {
    if (b == 0.0 && aPrime == 0.0) return 0.0;
    float h = degrees(atan(b, aPrime));
    return h < 0.0 ? h + 360.0 : h;
}

// x^7 by multiplication: pow() on lavapipe costs a log and an exp per lane.
float seventhPower(float x) {
    float square = x * x;
    return square * square * square * x;
}

// T = 1 - 0.17 cos(h - 30°) + 0.24 cos 2h + 0.32 cos(3h + 6°) - 0.20 cos(4h - 63°), from one
// sine and cosine by the multiple-angle identities: each cos() is a polynomial of many
// instructions per lane on lavapipe.
float hueWeight(float h) {
    float c1 = cos(h);
    float s1 = sin(h);
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

float ciede2000(vec3 lab1, vec3 lab2) {
    float c1 = length(lab1.yz);
    float c2 = length(lab2.yz);
    float cMean7 = seventhPower(0.5 * (c1 + c2));
    float g = 0.5 * (1.0 - sqrt(cMean7 / (cMean7 + 6103515625.0)));  // 25^7
    float a1 = (1.0 + g) * lab1.y;
    float a2 = (1.0 + g) * lab2.y;
    float cp1 = length(vec2(a1, lab1.z));
    float cp2 = length(vec2(a2, lab2.z));
    float hp1 = hueDegrees(lab1.z, a1);
    float hp2 = hueDegrees(lab2.z, a2);

    float dL = lab2.x - lab1.x;
    float dC = cp2 - cp1;
    float dh = 0.0;
    if (cp1 * cp2 != 0.0) {
        dh = hp2 - hp1;
        if (dh > 180.0) dh -= 360.0;
        else if (dh < -180.0) dh += 360.0;
    }
    float dH = 2.0 * sqrt(cp1 * cp2) * sin(radians(dh) * 0.5);

    float lMean = 0.5 * (lab1.x + lab2.x);
    float cMean = 0.5 * (cp1 + cp2);
    float hMean = hp1 + hp2;
    if (cp1 * cp2 != 0.0) {
        if (abs(hp1 - hp2) <= 180.0) hMean *= 0.5;
        else hMean = hMean < 360.0 ? 0.5 * (hMean + 360.0) : 0.5 * (hMean - 360.0);
    }
    float t = hueWeight(radians(hMean));
    float hueOffset = (hMean - 275.0) / 25.0;
    float dTheta = 30.0 * exp(-hueOffset * hueOffset);
    float cMeanP7 = seventhPower(cMean);
    float rC = 2.0 * sqrt(cMeanP7 / (cMeanP7 + 6103515625.0));
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

// Index into a 256-entry colour map: minDeltaE maps to the first entry, maxDeltaE to the last.
uint colormapEntry(float deltaE, float minDeltaE, float maxDeltaE) {
    float span = max(maxDeltaE - minDeltaE, 1e-6);
    return uint(round(clamp((deltaE - minDeltaE) / span, 0.0, 1.0) * 255.0));
}
