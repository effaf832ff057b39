// A representation of the user's own (groups/representation.h): SO(3) acting on the symmetric
// 3×3 matrices by S ↦ R S Rᵀ, with ρ'(ω) S = ΩS − SΩ, in the coordinates
// s = (S₁₁, S₂₂, S₃₃, √2 S₁₂, √2 S₁₃, √2 S₂₃), orthonormal for the Frobenius inner product, so
// that ρ(R) is orthogonal and γ ∈ R⁶ moves as a symmetric matrix Γ too. SO(3) ⋉ Sym(3) is the
// group of a rigid body in a field whose potential is linear in the body's orientation tensor
// (a gravity-gradient torque). Its Casimirs are the invariants of Γ: tr Γ, tr Γ², tr Γ³ (the
// stabiliser of a Γ with distinct eigenvalues is discrete, so the generic coadjoint orbits
// have dimension 2·3 and codimension 9 − 6 = 3). The same code is shown in
// docs/guide/defining-a-system.md, "A group made of groups".
#pragma once

#include <ddb/groups/semidirect_product.h>
#include <ddb/groups/so3.h>

#include <Eigen/Core>
#include <cmath>

namespace ddb::test {

struct SymmetricMatrices {
  static constexpr int kDim = 6;
  template <class T>
  using Map = Eigen::Matrix<T, 6, 6>;
  template <class T>
  using Coordinates = Eigen::Matrix<T, 6, 1>;
  template <class T>
  using Symmetric = Eigen::Matrix<T, 3, 3>;

  template <class T>
  static Symmetric<T> matrixOf(const Coordinates<T>& s) {
    const T r = T(1.0 / std::sqrt(2.0));
    Symmetric<T> S;
    S << s(0), s(3) * r, s(4) * r, s(3) * r, s(1), s(5) * r, s(4) * r, s(5) * r, s(2);
    return S;
  }
  template <class T>
  static Coordinates<T> coordinatesOf(const Symmetric<T>& S) {
    const T q = T(std::sqrt(2.0));
    Coordinates<T> s;
    s << S(0, 0), S(1, 1), S(2, 2), S(0, 1) * q, S(0, 2) * q, S(1, 2) * q;
    return s;
  }
  /// ρ(R): S ↦ R S Rᵀ, column by column.
  template <class T>
  static Map<T> ofGroup(const Eigen::Matrix<T, 3, 3>& R) {
    Map<T> m;
    for (int j = 0; j < kDim; ++j) {
      m.col(j) = coordinatesOf<T>(R * matrixOf<T>(Coordinates<T>::Unit(j)) * R.transpose());
    }
    return m;
  }
  /// ρ'(ω): S ↦ ΩS − SΩ.
  template <class T>
  static Map<T> ofAlgebra(const Eigen::Matrix<T, 3, 1>& w) {
    const Eigen::Matrix<T, 3, 3> Omega = SO3::hat(w);
    Map<T> m;
    for (int j = 0; j < kDim; ++j) {
      const Symmetric<T> S = matrixOf<T>(Coordinates<T>::Unit(j));
      m.col(j) = coordinatesOf<T>(Omega * S - S * Omega);
    }
    return m;
  }
};

}  // namespace ddb::test

namespace ddb {

template <>
struct SemidirectProductTraits<SO3, test::SymmetricMatrices> {
  static constexpr const char* kName = "SO3 x| Sym3";
  static constexpr int kNumCasimirs = 3;
  /// tr Γ, tr Γ², tr Γ³.
  template <class T>
  static Eigen::Matrix<T, 3, 1> casimirs(const Eigen::Matrix<T, 3, 1>&,
                                         const Eigen::Matrix<T, 6, 1>& gamma) {
    const Eigen::Matrix<T, 3, 3> G = test::SymmetricMatrices::matrixOf<T>(gamma);
    const Eigen::Matrix<T, 3, 3> G2 = G * G;
    return Eigen::Matrix<T, 3, 1>(G.trace(), G2.trace(), (G2 * G).trace());
  }
};

}  // namespace ddb
