// Helpers of the return-mapping tests (return_mapping.cc: von Mises and
// Drucker-Prager; mohr_coulomb_return_mapping.cc): three-dimensional models
// made as the material library makes them, a portable pseudo-random source,
// and the principal-space algebra of the elastic law used to build trial
// stresses backwards from a chosen return.
//
// Tolerances: every check compares quantities computed with O(10-100)
// floating-point operations on numbers of the size of the trial stress, so
// stresses are compared to 1e-12 of the stress scale (the size of the trial
// stress), and so are the yield functions (tighter than the 1e-10 the
// models must reach);
// multipliers and plastic strains, which are differences of stresses divided
// by the moduli, to 1e-10 relatively (the multipliers used are such that
// G d gamma is at least 1e-3 of the stress scale).

#ifndef mpm_otm_tests_unit_return_mapping_h
#define mpm_otm_tests_unit_return_mapping_h

#include <mpm_otm/base/plugins.h>
#include <mpm_otm/materials/material.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>

#include "../tests.h"

namespace ReturnMappingTests
{
  using namespace MpmOtm;
  using namespace MpmOtmTests;

  using Entries = std::vector<std::pair<std::string, std::string>>;

  // E = 1000, nu = 0.3: G = 1000 / 2.6, K = 1000 / 1.2.
  constexpr double E      = 1000.;
  constexpr double nu     = 0.3;
  const double     G      = E / (2. * (1. + nu));
  const double     K      = E / (3. * (1. - 2. * nu));
  const double     lambda = K - 2. / 3. * G;

  /**
   * A three-dimensional material @p model with the entries @p entries of its
   * subsection, made as the material library makes it.
   */
  template <typename Model>
  std::unique_ptr<Model>
  make_model(const std::string &model, const Entries &entries)
  {
    ParameterHandler prm;
    Material<3>::declare_common_parameters(
      prm,
      PluginRegistry<Material<3>>::selection(),
      "");
    PluginRegistry<Material<3>>::declare_parameters(prm);
    prm.set("Model", model);
    prm.set("Young's modulus", E);
    prm.set("Poisson's ratio", nu);
    prm.enter_subsection(model);
    for (const auto &entry : entries)
      prm.set(entry.first, entry.second);
    prm.leave_subsection();
    auto   material = PluginRegistry<Material<3>>::create(model);
    Model *result   = dynamic_cast<Model *>(material.get());
    check(result != nullptr, model + ": wrong class");
    material.release();
    result->parse_parameters(prm);
    return std::unique_ptr<Model>(result);
  }

  /**
   * Deterministic pseudo-random numbers: the raw output of std::mt19937 is
   * fixed by the standard (the distributions are not).
   */
  class Random
  {
  public:
    explicit Random(const unsigned int seed)
      : generator(seed)
    {}

    double
    uniform(const double a, const double b)
    {
      return a + (b - a) * (generator() / 4294967296.);
    }

  private:
    std::mt19937 generator;
  };

  /**
   * A rotation from a random unit quaternion.
   */
  inline Tensor<2, 3>
  random_rotation(Random &random)
  {
    double q[4], norm = 0;
    do
      {
        norm = 0;
        for (double &x : q)
          {
            x = random.uniform(-1., 1.);
            norm += x * x;
          }
    } while (norm > 1. || norm < 1e-2);
    for (double &x : q)
      x /= std::sqrt(norm);
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    Tensor<2, 3> R;
    R[0][0] = 1 - 2 * (y * y + z * z);
    R[0][1] = 2 * (x * y - z * w);
    R[0][2] = 2 * (x * z + y * w);
    R[1][0] = 2 * (x * y + z * w);
    R[1][1] = 1 - 2 * (x * x + z * z);
    R[1][2] = 2 * (y * z - x * w);
    R[2][0] = 2 * (x * z - y * w);
    R[2][1] = 2 * (y * z + x * w);
    R[2][2] = 1 - 2 * (x * x + y * y);
    return R;
  }

  /**
   * sum_i principal[i] q_i q_i^T with q_i the columns of @p Q.
   */
  inline SymmetricTensor<2, 3>
  from_principal(const std::array<double, 3> &principal, const Tensor<2, 3> &Q)
  {
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          result[i][j] += principal[k] * Q[i][k] * Q[j][k];
    return result;
  }

  inline std::array<double, 3>
  sorted_eigenvalues(const SymmetricTensor<2, 3> &stress)
  {
    const auto pairs =
      eigenvectors(stress, SymmetricTensorEigenvectorMethod::jacobi);
    return {{pairs[0].first, pairs[1].first, pairs[2].first}};
  }

  inline double
  norm(const std::array<double, 3> &a)
  {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  }

  /**
   * D n in principal space: 2 G n + lambda tr(n) (1, 1, 1).
   */
  inline std::array<double, 3>
  elastic(const std::array<double, 3> &n)
  {
    const double tr = n[0] + n[1] + n[2];
    return {{2. * G * n[0] + lambda * tr,
             2. * G * n[1] + lambda * tr,
             2. * G * n[2] + lambda * tr}};
  }

  /**
   * C^-1 s in principal space (the elastic strain of the stress s).
   */
  inline std::array<double, 3>
  compliance(const std::array<double, 3> &s)
  {
    const double          tr = s[0] + s[1] + s[2];
    std::array<double, 3> e;
    for (unsigned int k = 0; k < 3; ++k)
      e[k] = (s[k] - lambda / (3. * K) * tr) / (2. * G);
    return e;
  }

  /**
   * a + sum_j c_j b_j.
   */
  inline std::array<double, 3>
  combine(std::array<double, 3>                                        a,
          const std::vector<std::pair<double, std::array<double, 3>>> &terms)
  {
    for (const auto &term : terms)
      for (unsigned int k = 0; k < 3; ++k)
        a[k] += term.first * term.second[k];
    return a;
  }

  inline double
  difference(const std::array<double, 3> &a, const std::array<double, 3> &b)
  {
    return std::max(
      {std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
  }

  inline double
  scale_of(const SymmetricTensor<2, 3> &stress)
  {
    return std::max(stress.norm(), 1.);
  }
} // namespace ReturnMappingTests

#endif
