#pragma once
/// @file FreeSurface.h
/// @brief Free-surface detection of Koshizuka & Oka (1996), thesis Eq. 2.10: a particle is on
/// the free surface when n* < beta n0 (the study uses beta = 0.97), and its pressure is zero.

namespace wcmps {

struct FreeSurface_Koshizuka1996 {
  double beta;  ///< threshold (-), 0.8 ... 0.99 in the literature
  double n0;

  bool is_surface(double n) const { return n < beta * n0; }
};

}  // namespace wcmps
