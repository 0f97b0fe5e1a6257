// d'Eon's better dipole (E. d'Eon, "A Better Dipole", 2012; --profile
// better-dipole, docs/design.md §2 "Profile models"), in double
// precision: the classical dipole (physics/dipole.h) with
//  * Grosjean's diffusion coefficient D = (2σa + σs′) / (3σt′²) and σtr = √(σa/D),
//  * the boundary from the Fresnel moments of light inside, C1 and C2:
//    A = (1 + 3C2) / (1 − 2C1), the image plane at zb = 2AD above the surface,
//    the virtual source at zv = zr + 4AD (zr = 1/σt′, as the classical),
//  * the exitance through the boundary from both the fluence and the flux,
//    Rd = α′ (Cφ φ(r) + CE E(r)), Cφ = (1 − 2C1)/4, CE = (1 − 3C2)/2, with
//    φ = (e^(−σtr dr)/dr − e^(−σtr dv)/dv) / (4πD) and
//    E = (zr(1 + σtr dr)e^(−σtr dr)/dr³ + zv(1 + σtr dv)e^(−σtr dv)/dv³) / 4π.
// Rd is the flux leaving into air (Fresnel transmission included), so the
// normalised exit term (physics/fresnel.h) turns it into radiance.
#pragma once

namespace tsis {

// One wavelength band.
struct BetterDipoleChannel {
    BetterDipoleChannel(double sigmaSPrime, double sigmaA, double eta);
    // With the moments C1, C2 of the reflectance from inside given (tables
    // that build many channels of one η compute them once).
    BetterDipoleChannel(double sigmaSPrime, double sigmaA, double c1, double c2);

    // The exitance at r of a unit point source at depth z and its image
    // (Cφ φ + CE E per unit power); photon beam diffusion sums these.
    double pointSource(double z, double r) const;
    double Rd(double r) const { return alphaPrime * pointSource(zr, r); }  // mm⁻²
    double totalReflectance() const;  // closed-form ∫ Rd 2πr dr

    double sigmaTPrime, alphaPrime, D, sigmaTr, cPhi, cE, zb, zr;
};

}  // namespace tsis
