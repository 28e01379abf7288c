// FGD and TIR lookups from the tables of core/material/FgdTables.h, uploaded as 3D textures in
// their flat layout: FGD is (x kappa, y eta, z alpha + Nalpha * mu) and TIR is (x eta, y alpha,
// z mu). Node k of an axis with N nodes sits at the texel centre (k + 0.5) / N, so hardware
// trilinear filtering is the CPU's multilinear interpolation; mu of the FGD is blended by hand
// so that alpha never mixes across slabs.

struct TableAxis {
    float count;
    float minimum;
    float maximum;
};

float nodeCoordinate(TableAxis axis, float x) {
    return clamp((x - axis.minimum) / (axis.maximum - axis.minimum) * (axis.count - 1.0), 0.0,
                 axis.count - 1.0);
}

float texelCentre(float node, float count) { return (node + 0.5) / count; }

float fgdLookup(sampler3D fgd, TableAxis mu, TableAxis alpha, TableAxis eta, TableAxis kappa,
                float cosTheta, float roughness, float relativeEta, float relativeKappa) {
    float x = texelCentre(nodeCoordinate(kappa, relativeKappa), kappa.count);
    float y = texelCentre(nodeCoordinate(eta, relativeEta), eta.count);
    float alphaNode = nodeCoordinate(alpha, roughness);
    float muNode = nodeCoordinate(mu, cosTheta);
    float lowerSlab = min(floor(muNode), mu.count - 2.0);
    float depth = alpha.count * mu.count;
    float lower = texture(fgd, vec3(x, y, texelCentre(alphaNode + lowerSlab * alpha.count, depth))).r;
    float upper = texture(fgd, vec3(x, y, texelCentre(alphaNode + (lowerSlab + 1.0) * alpha.count, depth))).r;
    return mix(lower, upper, muNode - lowerSlab);
}

float tirLookup(sampler3D tir, TableAxis mu, TableAxis alpha, TableAxis eta, float cosTheta,
                float roughness, float relativeEta) {
    return texture(tir, vec3(texelCentre(nodeCoordinate(eta, relativeEta), eta.count),
                             texelCentre(nodeCoordinate(alpha, roughness), alpha.count),
                             texelCentre(nodeCoordinate(mu, cosTheta), mu.count))).r;
}
