// Closed-form box averages and frequency-clamping weights; see prefilter.h.
#include "scene/prefilter.h"

#include <algorithm>
#include <cmath>

namespace aliaslab {
namespace {

constexpr double kPiD = 3.14159265358979323846;

/// True when a box of half-width h around t is too narrow to average in
/// double precision: the point value is used instead.
bool negligible(double t, double h) { return !(h > 1e-9 * std::max(1.0, std::abs(t))); }

/// Antiderivative of s(t) = (-1)^floor(t) from 0: a triangle wave of period 2.
double checkerSignIntegral(double t) { return 1.0 - std::abs(t - 2.0 * std::floor(0.5 * t) - 1.0); }

/// Antiderivative of the square wave (1 on frac(u) < 1/2) from 0.
double squareWaveIntegral(double u) {
  const double f = std::floor(u);
  return 0.5 * f + std::min(u - f, 0.5);
}

double sinc(double t) { return std::abs(t) < 1e-12 ? 1.0 : std::sin(kPiD * t) / (kPiD * t); }

}  // namespace

float octaveWeight(float lambda, float width) {
  if (!(width > 0.f)) return 1.f;
  return std::clamp(std::log2(lambda / width), 0.f, 1.f);
}

double checkerSignAverage(double t, double h) {
  if (negligible(t, h)) return (static_cast<long long>(std::floor(t)) & 1) ? -1.0 : 1.0;
  return (checkerSignIntegral(t + h) - checkerSignIntegral(t - h)) / (2.0 * h);
}

double squareWaveAverage(double u, double h) {
  if (negligible(u, h)) return u - std::floor(u) < 0.5 ? 1.0 : 0.0;
  return (squareWaveIntegral(u + h) - squareWaveIntegral(u - h)) / (2.0 * h);
}

double sineIntegral(double x) {
  const double ax = std::abs(x);
  double si;
  if (ax <= 20.0) {
    // Si(x) = sum_n (-1)^n x^(2n+1) / ((2n+1) (2n+1)!)
    double term = ax, sum = 0;  // term = (-1)^n x^(2n+1) / (2n+1)!
    for (int n = 0; n < 80; ++n) {
      const double add = term / (2 * n + 1);
      sum += add;
      if (std::abs(add) < 1e-18 * std::max(1.0, std::abs(sum)) && n > 4) break;
      term *= -ax * ax / ((2.0 * n + 2) * (2.0 * n + 3));
    }
    si = sum;
  } else {
    // Si(x) = pi/2 - f(x) cos x - g(x) sin x with the asymptotic series
    // f ~ (1/x) sum (-1)^k (2k)! / x^(2k), g ~ (1/x^2) sum (-1)^k (2k+1)! / x^(2k).
    double f = 0, g = 0, tf = 1, tg = 1;
    const double inv2 = 1.0 / (ax * ax);
    for (int k = 0; k < 10; ++k) {
      f += tf, g += tg;
      tf *= -(2.0 * k + 1) * (2.0 * k + 2) * inv2;
      tg *= -(2.0 * k + 2) * (2.0 * k + 3) * inv2;
    }
    f /= ax, g *= inv2;
    si = 0.5 * kPiD - f * std::cos(ax) - g * std::sin(ax);
  }
  return x < 0 ? -si : si;
}

double sincAverage(double t, double h) {
  if (negligible(t, h)) return sinc(t);
  // integral of sin(pi s)/(pi s) ds = Si(pi s) / pi
  return (sineIntegral(kPiD * (t + h)) - sineIntegral(kPiD * (t - h))) / (2.0 * kPiD * h);
}

double boxAttenuation(double x) { return std::abs(x) < 1e-9 ? 1.0 : std::sin(x) / x; }

}  // namespace aliaslab
