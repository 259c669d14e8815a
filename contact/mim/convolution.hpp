// FFT-based products of Toeplitz influence matrices with element fields on an
// mx x my grid (zero-padded circular convolution; e.g. Liu, Wang & Liu 2000,
// "A versatile method of discrete convolution and FFT (DC-FFT)").
//
// out(i, j) = sum_{k,l} K(i - k, j - l) in(k, l)   for 0 <= i, k < mx, 0 <= j, l < my,
// with the kernel K given at offsets -(mx-1)..(mx-1) x -(my-1)..(my-1). The
// fields are zero-padded to an FFT-friendly size >= (2mx - 1) x (2my - 1), so
// the circular wrap never reaches the grid. Plans and buffers are created once
// (constructor); apply() allocates nothing. One Convolution per thread; FFTW's
// planner is not thread-safe, so plan creation and destruction are serialised
// by railsim::fftw_planner_mutex() (core/fftw_planner_lock.hpp) inside the
// constructor and destructor (callers need not, and must not, hold it around a
// solve). Units: whatever the kernel carries.
#pragma once

#include <complex>
#include <functional>
#include <vector>

namespace railsim::contact::mim {

class Convolution {
 public:
  // n_kernels: number of kernel slots. fftw_flags: FFTW planner flags
  // (FFTW_ESTIMATE plans instantly; FFTW_MEASURE plans slower, runs faster).
  Convolution(int mx, int my, int n_kernels, unsigned fftw_flags);
  ~Convolution();
  Convolution(const Convolution&) = delete;
  Convolution& operator=(const Convolution&) = delete;

  int mx() const { return mx_; }
  int my() const { return my_; }

  // Store the transform of kernel k(dx_index, dy_index) in slot `slot`.
  void set_kernel(int slot, const std::function<double(int, int)>& k);
  // Set the kernel from a table on offsets: table[(di + mx - 1) + (2 mx - 1) (dj + my - 1)].
  void set_kernel_table(int slot, const double* table);

  // out = K[slot] * in (scalar field).
  void apply(int slot, const double* in, double* out);
  // 2x2 block product: ox = Kxx*ix + Kxy*iy, oy = Kyx*ix + Kyy*iy.
  void apply_block(int sxx, int sxy, int syx, int syy, const double* ix, const double* iy,
                   double* ox, double* oy);

 private:
  void release();
  void load(const double* in, double* padded);
  void store(const double* padded, double* out) const;

  int mx_, my_;    // grid
  int n0_, n1_;    // padded size: n0 rows (y), n1 columns (x, fastest)
  int nc_;         // complex row length n1/2 + 1
  double* rin_ = nullptr;   // padded real input (padding stays zero)
  double* rin2_ = nullptr;  // second padded real input
  double* rout_ = nullptr;  // padded real output
  std::complex<double>* c1_ = nullptr;
  std::complex<double>* c2_ = nullptr;
  std::vector<std::complex<double>*> kernels_;
  void* plan_fwd_ = nullptr;
  void* plan_inv_ = nullptr;
};

// Smallest n >= target whose prime factors are 2, 3, 5, 7.
int fft_friendly_size(int target);

}  // namespace railsim::contact::mim
