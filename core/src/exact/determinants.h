// Determinants and cross products of plane normals, written once as templates and evaluated
// with Approx (filtered) then Expansion (exact); det3<Approx> has its own tighter bound.
#pragma once

#include <array>
#include <cmath>

#include "exact/plane_store.h"

namespace kergen {

template <class T>
T det3(const T& a0, const T& a1, const T& a2, const T& b0, const T& b1, const T& b2, const T& c0,
       const T& c1, const T& c2) {
  return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0);
}
// The filtered determinant, the hottest formula of the LP and of vertex construction, with one
// bound instead of a running error per operation: for entries v +- e,
//   |det(exact) - det(v)| <= perm(|v| + e) - perm(|v|)   (multilinear expansion, term by term),
// plus the rounding of the double evaluation, below 8 eps perm(|v|); the two permanents' own
// rounding (at most 7 eps each, positive terms) is covered by 24 eps perm(|v| + e).
template <>
inline Approx det3<Approx>(const Approx& a0, const Approx& a1, const Approx& a2, const Approx& b0, const Approx& b1,
                           const Approx& b2, const Approx& c0, const Approx& c1, const Approx& c2) {
  const double m0 = b1.v * c2.v - b2.v * c1.v, m1 = b0.v * c2.v - b2.v * c0.v, m2 = b0.v * c1.v - b1.v * c0.v;
  const double det = a0.v * m0 - a1.v * m1 + a2.v * m2;
  const double A0 = std::fabs(a0.v), A1 = std::fabs(a1.v), A2 = std::fabs(a2.v), B0 = std::fabs(b0.v),
               B1 = std::fabs(b1.v), B2 = std::fabs(b2.v), C0 = std::fabs(c0.v), C1 = std::fabs(c1.v),
               C2 = std::fabs(c2.v);
  const double perm = A0 * (B1 * C2 + B2 * C1) + A1 * (B0 * C2 + B2 * C0) + A2 * (B0 * C1 + B1 * C0);
  const double E0 = A0 + a0.e, E1 = A1 + a1.e, E2 = A2 + a2.e, F0 = B0 + b0.e, F1 = B1 + b1.e, F2 = B2 + b2.e,
               G0 = C0 + c0.e, G1 = C1 + c1.e, G2 = C2 + c2.e;
  const double perm_e = E0 * (F1 * G2 + F2 * G1) + E1 * (F0 * G2 + F2 * G0) + E2 * (F0 * G1 + F1 * G0);
  const double err = ((perm_e - perm) + 32 * exact::kEps * perm_e) * exact::kBoundScale + exact::kUnderflowFloor;
  return {det, err};
}

template <class T>
T det3_normals(const PlaneCoef<T>& p, const PlaneCoef<T>& q, const PlaneCoef<T>& r) {
  return det3(p.n[0], p.n[1], p.n[2], q.n[0], q.n[1], q.n[2], r.n[0], r.n[1], r.n[2]);
}
// n_p x n_q: the direction of the line of planes p and q.
template <class T>
std::array<T, 3> cross_normals(const PlaneCoef<T>& p, const PlaneCoef<T>& q) {
  return {p.n[1] * q.n[2] - p.n[2] * q.n[1], p.n[2] * q.n[0] - p.n[0] * q.n[2],
          p.n[0] * q.n[1] - p.n[1] * q.n[0]};
}

}  // namespace kergen
