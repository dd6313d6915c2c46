// The quadric error metric of Garland and Heckbert ("Surface Simplification Using Quadric Error
// Metrics", SIGGRAPH 1997): the weighted sum of squared distances to a set of planes, stored as
// the 10 distinct coefficients of a symmetric 4x4 matrix so that sums of quadrics are sums of
// coefficients.
#pragma once

#include <glm/vec3.hpp>

namespace rastrace::lod_detail {

struct Quadric {
  // Row-major upper triangle of [A b; b^T c].
  double a00 = 0, a01 = 0, a02 = 0, b0 = 0, a11 = 0, a12 = 0, b1 = 0, a22 = 0, b2 = 0, c = 0;

  // weight * (n . p + d)^2 for a unit normal n.
  static Quadric plane(const glm::dvec3& n, double d, double weight) {
    Quadric q;
    q.a00 = weight * n.x * n.x, q.a01 = weight * n.x * n.y, q.a02 = weight * n.x * n.z, q.b0 = weight * n.x * d;
    q.a11 = weight * n.y * n.y, q.a12 = weight * n.y * n.z, q.b1 = weight * n.y * d;
    q.a22 = weight * n.z * n.z, q.b2 = weight * n.z * d;
    q.c = weight * d * d;
    return q;
  }

  Quadric& operator+=(const Quadric& o) {
    a00 += o.a00, a01 += o.a01, a02 += o.a02, b0 += o.b0, a11 += o.a11;
    a12 += o.a12, b1 += o.b1, a22 += o.a22, b2 += o.b2, c += o.c;
    return *this;
  }

  double evaluate(const glm::dvec3& p) const {
    const double x = p.x, y = p.y, z = p.z;
    const double v = a00 * x * x + a11 * y * y + a22 * z * z + 2.0 * (a01 * x * y + a02 * x * z + a12 * y * z) +
                     2.0 * (b0 * x + b1 * y + b2 * z) + c;
    return v > 0.0 ? v : 0.0;  // a sum of squares; rounding may dip below zero
  }
};

inline Quadric operator+(Quadric a, const Quadric& b) { return a += b; }

}  // namespace rastrace::lod_detail
