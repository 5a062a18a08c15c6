#ifndef shadelab_tests_Quadrature_h
#define shadelab_tests_Quadrature_h
// Composite Gauss-Legendre quadrature on graded grids: the tests' own
// integrator, independent of the adaptive Gauss-Kronrod in Albedo.cxx.

#include <algorithm>
#include <vector>

namespace shadelab
{
namespace test
{

// 12-point Gauss-Legendre on [-1, 1] (positive half; the rule is symmetric).
constexpr double kGaussX[6] = { 0.1252334085114689, 0.3678314989981802, 0.5873179542866175, 0.7699026741943047,
  0.9041172563704749, 0.9815606342467192 };
constexpr double kGaussW[6] = { 0.2491470458134028, 0.2334925365383548, 0.2031674267230659, 0.1600783285433462,
  0.1069393259953184, 0.0471753363865118 };

/// Integral of @p f over [a, b] by the 12-point rule.
template <class F>
double gaussLegendre(const F& f, double a, double b)
{
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    sum += kGaussW[i] * (f(c - h * kGaussX[i]) + f(c + h * kGaussX[i]));
  }
  return sum * h;
}

/// Breakpoints in [low, high]: the ends, every point of @p special and the
/// points at distances @p first * 3^k (k = 0, 1, ...) on either side of
/// each, plus a uniform grid of @p cells pieces.
inline std::vector<double> graded(
  double low, double high, const std::vector<double>& special, int cells, double first = 1e-6)
{
  std::vector<double> b{ low, high };
  for (int i = 1; i < cells; ++i)
  {
    b.push_back(low + (high - low) * i / cells);
  }
  for (double p : special)
  {
    b.push_back(p);
    for (double d = first; d < high - low; d *= 3.0)
    {
      b.push_back(p - d);
      b.push_back(p + d);
    }
  }
  std::vector<double> inside;
  for (double x : b)
  {
    if (x >= low && x <= high)
    {
      inside.push_back(x);
    }
  }
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  return inside;
}

/// Integral of @p f over [breaks.front(), breaks.back()], piece by piece.
template <class F>
double composite(const F& f, const std::vector<double>& breaks)
{
  double sum = 0.0;
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
  {
    sum += gaussLegendre(f, breaks[i], breaks[i + 1]);
  }
  return sum;
}

} // namespace test
} // namespace shadelab

#endif
