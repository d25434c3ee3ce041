#pragma once
// Drag on a parcel for the coupling: the parcel carries l^3 originals, each seeing the gas as an
// original particle does, so F_parcel = l^3 F_drag(d_orig, Re_p(d_orig), eps) with the ORIGINAL
// diameter in the drag law and in Re_p (Sakai & Koshizuka 2009, Chem. Eng. Sci. 64:533;
// docs/physics.md, Coarse-graining rules). This keeps each original's relaxation time. The parcel
// diameter in the drag law instead would make the Stokes drag per unit mass l^2 too small (3 pi mu
// d u ~ l against m ~ l^3).
namespace lbdem::cg {

struct DragScaling {
  double factor;             // F_parcel / F_one_original = l^3 [-]
  double original_diameter;  // diameter to use in the drag law and Re_p [m]
};

inline DragScaling drag_scaling(double parcel_diameter, double l) {
  return {l * l * l, parcel_diameter / l};
}

}  // namespace lbdem::cg
