// First-order (paraxial) optics of a prescription, by y-nu ray tracing at one wavelength.
#pragma once
#include <utility>
#include <vector>

#include "optics/dispersion.h"
#include "optics/lens_prescription.h"

namespace objektiv {

struct ParaxialData {
  double efl = 0;  // effective focal length, mm
  double bfl = 0;  // back focal length: last vertex to the paraxial focus, mm
  double ffl = 0;  // front focal length: first vertex to the front focus (negative: in front), mm
  // Pupils: the stop imaged through the elements in front of it (entrance) and behind it
  // (exit). Positions from the first / last vertex, positive toward the film.
  double entrance_pupil_position = 0, entrance_pupil_diameter = 0;
  double exit_pupil_position = 0, exit_pupil_diameter = 0;
  double fnumber = 0;  // EFL / entrance pupil diameter (object at infinity)
  // The object space's index (1: air). The EFL is the image side's (in air); the front focal
  // length, object side, is object_index x EFL, and a field angle theta there images at
  // object_index x EFL x tan(theta).
  double object_index = 1;
  // Principal planes, from the first / last vertex (positive toward the film). In air the
  // nodal points coincide with them (not where the object space is another medium).
  double front_principal_plane = 0, back_principal_plane = 0;
};

// The index after each surface at lambda_nm, signed with the direction of travel (negative
// after an odd number of mirrors: lens designers' convention, with which the y-nu equations
// hold unchanged through mirrors, n' = -n there, and thicknesses are negative where the
// index is). Entry i + 1 is the medium after surface i; entry 0 the object space (air).
std::vector<double> SignedIndices(const LensPrescription& lens, double lambda_nm);

// A paraxial ray meeting the first surface at height y with reduced angle nu (n u in the object
// medium) carried through the whole lens (gradient-index media included): its height and
// reduced angle after the last surface; `heights`, if given, receives its height at each surface.
std::pair<double, double> TraceParaxialForward(const LensPrescription& lens, double lambda_nm, double y, double nu,
                                               std::vector<double>* heights = nullptr);

// Object at infinity. Surfaces are refracted with their indices at lambda_nm.
// stop_semi_diameter < 0: the prescription's stop.
ParaxialData ComputeParaxial(const LensPrescription& lens, double lambda_nm = kLambdad, double stop_semi_diameter = -1);

// The lens scaled so that its paraxial EFL at the d line is `focal_length` mm.
LensPrescription ScaledToFocalLength(const LensPrescription& lens, double focal_length);

}  // namespace objektiv
