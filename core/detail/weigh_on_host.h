// detail::weighOnHost: m̂ ← w ∘ m̂ for the named weights of core/eigenbasis_weights.h, for an
// eigenbasis whose coordinates are on the host (the dense and distributed backends'), through
// its entry loop; their weigh() members call it, so the loops over the three weights are written
// once. The half phases are formed once per index, not per entry.
#pragma once

#include <ddb/core/eigenbasis_weights.h>

#include <Eigen/Core>
#include <complex>

namespace ddb {

namespace detail {

/// half_a = e^{iτθ_a/2} for every phase (one sine and cosine per index, not per entry).
inline void fillHalfPhases(double tau, const Eigen::VectorXd& theta, Eigen::VectorXcd& half) {
  half.resize(theta.size());
  for (Eigen::Index a = 0; a < theta.size(); ++a) {
    double re, im;
    halfPhaseParts(tau, theta(a), re, im);
    half(a) = std::complex<double>(re, im);
  }
}

/// m̂ ← w ∘ m̂ through the eigenbasis's entry map: map_entries(f) calls
/// f(a, b, m̂_ab) for each entry it holds and stores the result (the dense backend's every
/// entry, a distributed rank's own). theta the phases; half a workspace for the half phases.
template <class MapEntries>
void weighOnHost(const PhaseFunctionWeights& w, const Eigen::VectorXd& theta, Eigen::VectorXcd&,
                 const MapEntries& map_entries) {
  map_entries([&](Eigen::Index a, Eigen::Index b, std::complex<double> value) {
    double re, im;
    phaseFunctionParts(w.f, w.scale * (theta(a) - theta(b)), re, im);
    return value * std::complex<double>(re, im);
  });
}

template <class MapEntries>
void weighOnHost(const ConjugationDerivativeWeights& w, const Eigen::VectorXd& theta,
                 Eigen::VectorXcd& half, const MapEntries& map_entries) {
  fillHalfPhases(w.tau, theta, half);
  map_entries([&](Eigen::Index a, Eigen::Index c, std::complex<double> value) {
    double re, im;
    conjugationDerivativeWeightParts(w.tau, theta(a), theta(c), half(a).real(), half(a).imag(),
                                     half(c).real(), half(c).imag(), re, im);
    return value * std::complex<double>(re, im);
  });
}

template <class MapEntries>
void weighOnHost(const RowPhaseWeights& w, const Eigen::VectorXd& theta, Eigen::VectorXcd& half,
                 const MapEntries& map_entries) {
  fillHalfPhases(w.tau, theta, half);
  map_entries([&](Eigen::Index a, Eigen::Index, std::complex<double> value) {
    double re, im;
    rowPhaseWeightParts(half(a).real(), half(a).imag(), re, im);
    return value * std::complex<double>(re, im);
  });
}

}  // namespace detail

}  // namespace ddb
