// Data: refractiveindex.info database (public domain, CC0 1.0), visible-range rows of
//   Au, Ag, Cu: P. B. Johnson and R. W. Christy, Phys. Rev. B 6, 4370 (1972);
//   Al: K. M. McPeak et al., ACS Photonics 2, 326 (2015), every 20 nm.
// Wavelengths in nm; the spectra are linear between rows and constant beyond the ends.
#include "base/conductor_data.h"

#include <vector>

namespace objektiv {
namespace {

struct Row {
  float lambda, n, k;
};

const Row kGold[] = {
    {354.2f, 1.50f, 1.866f}, {367.9f, 1.48f, 1.895f}, {381.5f, 1.46f, 1.933f}, {397.4f, 1.47f, 1.952f},
    {413.3f, 1.46f, 1.958f}, {430.5f, 1.45f, 1.948f}, {450.9f, 1.38f, 1.914f}, {471.4f, 1.31f, 1.849f},
    {495.9f, 1.04f, 1.833f}, {520.9f, 0.62f, 2.081f}, {548.6f, 0.43f, 2.455f}, {582.1f, 0.29f, 2.863f},
    {616.8f, 0.21f, 3.272f}, {659.5f, 0.14f, 3.697f}, {704.5f, 0.13f, 4.103f}, {756.0f, 0.14f, 4.542f},
    {821.1f, 0.16f, 5.083f}, {892.0f, 0.17f, 5.663f},
};

const Row kSilver[] = {
    {354.2f, 0.10f, 1.419f}, {367.9f, 0.07f, 1.657f}, {381.5f, 0.05f, 1.864f}, {397.4f, 0.05f, 2.070f},
    {413.3f, 0.05f, 2.275f}, {430.5f, 0.04f, 2.462f}, {450.9f, 0.04f, 2.657f}, {471.4f, 0.05f, 2.869f},
    {495.9f, 0.05f, 3.093f}, {520.9f, 0.05f, 3.324f}, {548.6f, 0.06f, 3.586f}, {582.1f, 0.05f, 3.858f},
    {616.8f, 0.06f, 4.152f}, {659.5f, 0.05f, 4.483f}, {704.5f, 0.04f, 4.838f}, {756.0f, 0.03f, 5.242f},
    {821.1f, 0.04f, 5.727f}, {892.0f, 0.04f, 6.312f},
};

const Row kCopper[] = {
    {354.2f, 1.37f, 1.916f}, {367.9f, 1.36f, 1.975f}, {381.5f, 1.33f, 2.045f}, {397.4f, 1.32f, 2.116f},
    {413.3f, 1.28f, 2.207f}, {430.5f, 1.25f, 2.305f}, {450.9f, 1.24f, 2.397f}, {471.4f, 1.25f, 2.483f},
    {495.9f, 1.22f, 2.564f}, {520.9f, 1.18f, 2.608f}, {548.6f, 1.02f, 2.577f}, {582.1f, 0.70f, 2.704f},
    {616.8f, 0.30f, 3.205f}, {659.5f, 0.22f, 3.747f}, {704.5f, 0.21f, 4.205f}, {756.0f, 0.24f, 4.665f},
    {821.1f, 0.26f, 5.180f}, {892.0f, 0.30f, 5.768f},
};

const Row kAluminium[] = {
    {360.f, 0.3001f, 3.7763f}, {380.f, 0.3360f, 4.0026f}, {400.f, 0.3752f, 4.2264f}, {420.f, 0.4176f, 4.4474f},
    {440.f, 0.4642f, 4.6691f}, {460.f, 0.5148f, 4.8879f}, {480.f, 0.5680f, 5.1059f}, {500.f, 0.6257f, 5.3205f},
    {520.f, 0.6883f, 5.5360f}, {540.f, 0.7545f, 5.7465f}, {560.f, 0.8292f, 5.9582f}, {580.f, 0.9086f, 6.1652f},
    {600.f, 0.9925f, 6.3690f}, {620.f, 1.0882f, 6.5666f}, {640.f, 1.1903f, 6.7594f}, {660.f, 1.3044f, 6.9424f},
    {680.f, 1.4260f, 7.1163f}, {700.f, 1.5598f, 7.2739f}, {720.f, 1.7068f, 7.4142f}, {740.f, 1.8722f, 7.5284f},
    {760.f, 2.0542f, 7.5995f}, {780.f, 2.2315f, 7.6039f}, {800.f, 2.3737f, 7.5226f}, {820.f, 2.4100f, 7.3694f},
    {840.f, 2.3018f, 7.2257f},
};

template <size_t N>
ConductorIndex FromRows(const Row (&rows)[N]) {
  std::vector<float> l, n, k;
  for (const Row& r : rows) {
    l.push_back(r.lambda);
    n.push_back(r.n);
    k.push_back(r.k);
  }
  return {Spectrum::Tabulated(l, n), Spectrum::Tabulated(l, k)};
}

}  // namespace

std::optional<ConductorIndex> NamedConductor(const std::string& name) {
  if (name == "none") return ConductorIndex{Spectrum(0.f), Spectrum(1.f)};
  if (name == "Au") return FromRows(kGold);
  if (name == "Ag") return FromRows(kSilver);
  if (name == "Cu") return FromRows(kCopper);
  if (name == "Al") return FromRows(kAluminium);
  return std::nullopt;
}

std::string NamedConductorList() { return "none, Au, Ag, Cu, Al"; }

}  // namespace objektiv
