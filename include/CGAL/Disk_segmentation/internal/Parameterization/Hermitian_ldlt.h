// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sparse LDL^H factorization of a Hermitian matrix, bit for bit Eigen's
// SimplicialLDLT, for the complex system of the free-border LSCM.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_HERMITIAN_LDLT_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_HERMITIAN_LDLT_H

#include <CGAL/disable_warnings.h>

#include <Eigen/Sparse>

#include <complex>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Sparse LDL^H of a Hermitian matrix already in elimination order, given by
// its upper triangle (column by column, rows sorted): the up-looking
// simplicial algorithm of Eigen's SimplicialLDLT, with the same operations
// in the same order, so that it gives the same factor and solutions bit for
// bit. The complex products of the inner loops are written out on the real
// and imaginary parts: std::complex's operator* checks every product for a
// NaN to redo it by the C99 rules, a branch that kept the loop from being
// scheduled well (the LSCM factorization was the largest part of the
// atlas's time, 19 % of refined_elephant x4's).
class Hermitian_ldlt
{
public:
  typedef std::complex<double> Complex;

  explicit Hermitian_ldlt(const Eigen::SparseMatrix<Complex>& upper) { ok_ = factorize(upper); }

  // False when a pivot is zero (the matrix is singular).
  bool ok() const { return ok_; }

  // Solves L D L^H x = b in place.
  void solve(Eigen::VectorXcd& x) const
  {
    const int n = int(diagonal_.size());
    const double* v = value_.data();
    for(int j = 0; j < n; ++j)
    {
      const double xr = x[j].real(), xi = x[j].imag();
      if(xr == 0. && xi == 0.)
        continue;  // as Eigen does: no product with a zero
      for(int p = start_[j]; p < start_[j + 1]; ++p)
      {
        const double lr = v[2 * p], li = v[2 * p + 1];
        Complex& y = x[row_[p]];
        y = Complex(y.real() - (xr * lr - xi * li), y.imag() - (xr * li + xi * lr));
      }
    }
    for(int j = 0; j < n; ++j)
    {
      // By the inverse, as Eigen's vectorized complex division forms it
      // (d / d^2), so that the charts stay the same.
      const double d = diagonal_[j], inverse = d / (d * d);
      x[j] = Complex(inverse * x[j].real(), inverse * x[j].imag());
    }
    for(int j = n - 1; j >= 0; --j)
    {
      double yr = x[j].real(), yi = x[j].imag();
      for(int p = start_[j]; p < start_[j + 1]; ++p)
      {
        const double lr = v[2 * p], li = v[2 * p + 1];
        const Complex& z = x[row_[p]];
        yr -= lr * z.real() + li * z.imag();
        yi -= lr * z.imag() - li * z.real();
      }
      x[j] = Complex(yr, yi);
    }
  }

private:
  bool factorize(const Eigen::SparseMatrix<Complex>& a)
  {
    const int n = int(a.cols());
    const int* outer = a.outerIndexPtr();
    const int* inner = a.innerIndexPtr();
    const Complex* entry = a.valuePtr();
    auto column_end = [&](int k) { return a.isCompressed() ? outer[k + 1] : outer[k] + a.innerNonZeroPtr()[k]; };

    // Elimination tree and the number of entries of each column of L.
    std::vector<int> parent(static_cast<std::size_t>(n), -1), mark(static_cast<std::size_t>(n), 0),
      count(static_cast<std::size_t>(n), 0);
    for(int k = 0; k < n; ++k)
    {
      mark[k] = k;
      for(int q = outer[k]; q < column_end(k); ++q)
        for(int i = inner[q]; i < k && mark[i] != k; i = parent[i])
        {
          if(parent[i] == -1)
            parent[i] = k;
          ++count[i];
          mark[i] = k;
        }
    }
    start_.assign(std::size_t(n) + 1, 0);
    for(int k = 0; k < n; ++k)
      start_[k + 1] = start_[k] + count[k];
    row_.resize(std::size_t(start_[n]));
    value_.resize(2 * std::size_t(start_[n]));
    diagonal_.assign(std::size_t(n), 0.);

    // Row k of L by a sparse triangular solve over the rows its pattern
    // (found up the tree) holds, in topological order.
    std::vector<double> y(2 * std::size_t(n), 0.);
    std::vector<int> pattern(static_cast<std::size_t>(n)), filled(static_cast<std::size_t>(n), 0);
    double* v = value_.data();
    for(int k = 0; k < n; ++k)
    {
      y[2 * k] = y[2 * k + 1] = 0.;
      int top = n;
      mark[k] = k;
      for(int q = outer[k]; q < column_end(k); ++q)
      {
        int i = inner[q];
        if(i > k)
          continue;
        y[2 * i] += entry[q].real();
        y[2 * i + 1] -= entry[q].imag();  // the conjugate
        int length = 0;
        for(; mark[i] != k; i = parent[i])
        {
          pattern[length++] = i;
          mark[i] = k;
        }
        while(length > 0)
          pattern[--top] = pattern[--length];
      }
      double d = y[2 * k];
      y[2 * k] = y[2 * k + 1] = 0.;
      for(; top < n; ++top)
      {
        const int i = pattern[top];
        const double yr = y[2 * i], yi = y[2 * i + 1];
        y[2 * i] = y[2 * i + 1] = 0.;
        const double lr = yr / diagonal_[i], li = yi / diagonal_[i];
        const int end = start_[i] + filled[i];
        int p = start_[i];
        for(; p < end; ++p)
        {
          // y -= conj(L(.., i)) * yi
          const double cr = v[2 * p], ci = v[2 * p + 1];
          double* target = &y[2 * std::size_t(row_[p])];
          target[0] -= cr * yr + ci * yi;
          target[1] -= cr * yi - ci * yr;
        }
        d -= lr * yr + li * yi;  // the real part of l_ki * conj(yi)
        row_[p] = k;
        v[2 * p] = lr;
        v[2 * p + 1] = li;
        ++filled[i];
      }
      diagonal_[k] = d;
      if(d == 0.)
        return false;
    }
    return true;
  }

  std::vector<int> start_, row_;  // L by columns, unit diagonal not stored
  std::vector<double> value_;     // real and imaginary parts, interleaved
  std::vector<double> diagonal_;
  bool ok_ = false;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_HERMITIAN_LDLT_H
