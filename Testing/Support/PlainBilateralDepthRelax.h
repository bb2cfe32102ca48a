// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef PlainBilateralDepthRelax_h
#define PlainBilateralDepthRelax_h

#include <cstddef>
#include <vector>

namespace vr::test
{
/** The plain reference of BilateralDepthRelaxFilter: Eq. 1 of docs/design.md "Relaxation" evaluated exactly as written,
 * in double, one pixel and one neighbour at a time, written independently of the fast kernel to check it and to time
 * it.
 *
 *   D'_p = ((1 - w) |Omega| D_p + w sum_q R(D_p - D_q) D_q) / ((1 - w) |Omega| + w sum_q R(D_p - D_q)),
 *   R(x) = exp(-a x^2), and R = 0 when a x^2 > -ln(FLT_MIN) (the filter's underflow rule).
 *
 * Jacobi: every pixel reads iteration k and writes k + 1; the state stays in double between iterations. Fixed
 * pixels (fixed[k] != 0; \a fixed may be empty) keep their value; a zero denominator keeps D_p.
 * \param depth row-major width x height depths in mm. \param relaxation w. \param anisotropy a in mm^-2.
 * \return the relaxed depths, row-major, in mm. */
std::vector<double>
PlainBilateralDepthRelax(const std::vector<float> &         depth,
                         const std::vector<unsigned char> & fixed,
                         std::size_t                        width,
                         std::size_t                        height,
                         double                             relaxation,
                         double                             anisotropy,
                         unsigned int                       iterations);

/** The fixed-point residual of a relaxed depth map, written independently of the solvers: the largest
 * |D_p - sum_q R(D_p - D_q) D_q / sum_q R(D_p - D_q)| over free pixels p whose weights do not all vanish, in mm,
 * with R(x) = exp(-a x^2) in double and R = 0 when a x^2 > -ln(FLT_MIN) (the filter's underflow rule). Where that
 * residual is 0, D is a fixed point of Eq. 1 for every w. \a fixed may be empty. */
double
PlainFixedPointResidual(const std::vector<double> &        depth,
                        const std::vector<unsigned char> & fixed,
                        std::size_t                        width,
                        std::size_t                        height,
                        double                             anisotropy);

/** The energy Jacobi's passes descend, sum over 4-neighbour edges of (1 - exp(-a (D_p - D_q)^2)) / (2a), in mm^2
 * (a = 0: sum of (D_p - D_q)^2 / 2), in double: the independent check that a solve reached the same minimum. */
double
PlainRelaxEnergy(const std::vector<double> & depth, std::size_t width, std::size_t height, double anisotropy);

/** Plain Jacobi passes of Eq. 1 (w = 1, in double, as PlainBilateralDepthRelax) until PlainFixedPointResidual()
 * falls to \a residual mm, checked every \a checkEvery passes, or \a maximumIterations passes; the test reference
 * for the steady solver. \return the depths; \a iterations receives the passes run. */
std::vector<double>
PlainJacobiToResidual(const std::vector<float> &         depth,
                      const std::vector<unsigned char> & fixed,
                      std::size_t                        width,
                      std::size_t                        height,
                      double                             anisotropy,
                      double                             residual,
                      unsigned int                       maximumIterations,
                      unsigned int &                     iterations,
                      unsigned int                       checkEvery = 50);

/** The hand-worked case of a 3 x 1 depth map [0, x, 3] whose two ends are fixed, w = 1, jump threshold \a J (mm):
 * one Jacobi pass takes the middle pixel to f(x) = (R(x) 0 + R(3 - x) 3) / (R(x) + R(3 - x)), R(d) = exp(-(d/J)^2).
 * \return f(\a x). */
double
ThreePixelMiddleAfterOnePass(double x, double J);

/** The fixed point x = f(x) of that case that Jacobi passes approach from x = 1 (bilateral weights allow several:
 * 1.5 is one, but from 1 the passes go to the one near 0.67 for J = 2), by plain iteration of f in double. */
double
ThreePixelMiddleFixedPoint(double J);
} // namespace vr::test

#endif
