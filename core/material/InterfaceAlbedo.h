#pragma once
// What the adding loop needs to know about one rough interface besides its roughness: how much
// it reflects (FGD) and how much upward light escapes through it (TIR). The tables implement
// it; tests substitute exact smooth Fresnel ("Fresnel mode" of docs/bsdf.md §8).
namespace matevo {

class InterfaceAlbedo {
public:
    virtual ~InterfaceAlbedo() = default;

    // FGD(mu, alpha, eta, kappa): directional albedo of a rough GGX interface with relative
    // complex index eta + i kappa, Fresnel included (docs/bsdf.md §3.1).
    virtual double reflectance(double cosTheta, double alpha, double eta, double kappa) const = 0;

    // TIR(mu, alpha, eta): fraction of light reflected towards the interface of relative index
    // eta (seen from below) that escapes through it (§3.4).
    virtual double escapeFraction(double cosTheta, double alpha, double eta) const = 0;
};

}  // namespace matevo
