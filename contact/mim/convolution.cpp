// Zero-padded FFT convolution with FFTW; see convolution.hpp.
#include "contact/mim/convolution.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "core/fftw_planner_lock.hpp"

namespace railsim::contact::mim {

int fft_friendly_size(int target) {
  for (int n = std::max(1, target);; ++n) {
    int m = n;
    for (int p : {2, 3, 5, 7})
      while (m % p == 0) m /= p;
    if (m == 1) return n;
  }
}

namespace {
fftw_plan as_plan(void* p) { return static_cast<fftw_plan>(p); }
std::string size_text(int n0, int n1) { return std::to_string(n0) + " x " + std::to_string(n1); }
fftw_complex* as_fc(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }
}  // namespace

Convolution::Convolution(int mx, int my, int n_kernels, unsigned fftw_flags)
    : mx_(mx), my_(my), n0_(fft_friendly_size(2 * my - 1)), n1_(fft_friendly_size(2 * mx - 1)) {
  nc_ = n1_ / 2 + 1;
  const std::size_t nr = static_cast<std::size_t>(n0_) * n1_;
  const std::size_t ncx = static_cast<std::size_t>(n0_) * nc_;
  rin_ = fftw_alloc_real(nr);
  rin2_ = fftw_alloc_real(nr);
  rout_ = fftw_alloc_real(nr);
  c1_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(ncx));
  c2_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(ncx));
  if (!rin_ || !rin2_ || !rout_ || !c1_ || !c2_) {
    release();
    throw railsim::NumericalError("mim convolution: out of memory for the FFT work arrays of " + size_text(n0_, n1_) +
                                  " points (grid " + size_text(mx, my) + "): use a coarser grid");
  }
  {
    // Plans first: FFTW_MEASURE overwrites the arrays while planning.
    std::lock_guard<std::mutex> lock(railsim::fftw_planner_mutex());
    plan_fwd_ = fftw_plan_dft_r2c_2d(n0_, n1_, rin_, as_fc(c1_), fftw_flags);
    plan_inv_ = fftw_plan_dft_c2r_2d(n0_, n1_, as_fc(c1_), rout_, fftw_flags);
  }
  if (!plan_fwd_ || !plan_inv_) {
    const char* which = !plan_fwd_ ? "forward (r2c)" : "inverse (c2r)";
    release();
    throw railsim::NumericalError(std::string("mim convolution: FFTW returned no plan (NULL) for the ") + which +
                                  " 2-D transform of " + size_text(n0_, n1_) + " points, flags " +
                                  std::to_string(fftw_flags) + " (out of memory, or FFTW_WISDOM_ONLY without wisdom)");
  }
  std::memset(rin_, 0, nr * sizeof(double));
  std::memset(rin2_, 0, nr * sizeof(double));
  kernels_.assign(n_kernels, nullptr);
  for (auto& k : kernels_) {
    k = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(ncx));
    if (!k) {
      release();
      throw railsim::NumericalError("mim convolution: out of memory for " + std::to_string(n_kernels) +
                                    " kernel spectra of " + size_text(n0_, nc_) + " points: use a coarser grid");
    }
    std::fill(k, k + ncx, std::complex<double>(0.0, 0.0));
  }
}

Convolution::~Convolution() { release(); }

void Convolution::release() {
  for (auto*& k : kernels_) fftw_free(k), k = nullptr;
  {
    std::lock_guard<std::mutex> lock(railsim::fftw_planner_mutex());
    if (plan_fwd_) fftw_destroy_plan(as_plan(plan_fwd_));
    if (plan_inv_) fftw_destroy_plan(as_plan(plan_inv_));
    plan_fwd_ = plan_inv_ = nullptr;
  }
  fftw_free(rin_);
  fftw_free(rin2_);
  fftw_free(rout_);
  fftw_free(c1_);
  fftw_free(c2_);
  rin_ = rin2_ = rout_ = nullptr;
  c1_ = c2_ = nullptr;
}

void Convolution::set_kernel(int slot, const std::function<double(int, int)>& k) {
  const std::size_t nr = static_cast<std::size_t>(n0_) * n1_;
  double* buf = rout_;  // scratch (FFTW-aligned); rout_ holds no state between calls
  std::fill(buf, buf + nr, 0.0);
  for (int dj = -(my_ - 1); dj <= my_ - 1; ++dj)
    for (int di = -(mx_ - 1); di <= mx_ - 1; ++di) {
      const int r = (dj + n0_) % n0_, c = (di + n1_) % n1_;
      buf[static_cast<std::size_t>(r) * n1_ + c] = k(di, dj);
    }
  // Fold the inverse-transform normalisation into the kernel.
  const double scale = 1.0 / static_cast<double>(nr);
  for (std::size_t q = 0; q < nr; ++q) buf[q] *= scale;
  fftw_execute_dft_r2c(as_plan(plan_fwd_), buf, as_fc(kernels_.at(slot)));
}

void Convolution::set_kernel_table(int slot, const double* table) {
  const int w = 2 * mx_ - 1;
  set_kernel(slot, [&](int di, int dj) {
    return table[static_cast<std::size_t>(di + mx_ - 1) + static_cast<std::size_t>(w) * (dj + my_ - 1)];
  });
}

void Convolution::load(const double* in, double* padded) {
  for (int j = 0; j < my_; ++j)
    std::memcpy(padded + static_cast<std::size_t>(j) * n1_, in + static_cast<std::size_t>(j) * mx_,
                mx_ * sizeof(double));
}

void Convolution::store(const double* padded, double* out) const {
  for (int j = 0; j < my_; ++j)
    std::memcpy(out + static_cast<std::size_t>(j) * mx_, padded + static_cast<std::size_t>(j) * n1_,
                mx_ * sizeof(double));
}

void Convolution::apply(int slot, const double* in, double* out) {
  load(in, rin_);
  fftw_execute_dft_r2c(as_plan(plan_fwd_), rin_, as_fc(c1_));
  const std::complex<double>* k = kernels_[slot];
  const std::size_t ncx = static_cast<std::size_t>(n0_) * nc_;
  for (std::size_t q = 0; q < ncx; ++q) c1_[q] *= k[q];
  fftw_execute_dft_c2r(as_plan(plan_inv_), as_fc(c1_), rout_);
  store(rout_, out);
}

void Convolution::apply_block(int sxx, int sxy, int syx, int syy, const double* ix, const double* iy,
                              double* ox, double* oy) {
  load(ix, rin_);
  load(iy, rin2_);
  fftw_execute_dft_r2c(as_plan(plan_fwd_), rin_, as_fc(c1_));
  fftw_execute_dft_r2c(as_plan(plan_fwd_), rin2_, as_fc(c2_));
  const std::complex<double>* kxx = kernels_[sxx];
  const std::complex<double>* kxy = kernels_[sxy];
  const std::complex<double>* kyx = kernels_[syx];
  const std::complex<double>* kyy = kernels_[syy];
  const std::size_t ncx = static_cast<std::size_t>(n0_) * nc_;
  for (std::size_t q = 0; q < ncx; ++q) {
    const std::complex<double> X = c1_[q], Y = c2_[q];
    c1_[q] = kxx[q] * X + kxy[q] * Y;
    c2_[q] = kyx[q] * X + kyy[q] * Y;
  }
  fftw_execute_dft_c2r(as_plan(plan_inv_), as_fc(c1_), rout_);
  store(rout_, ox);
  fftw_execute_dft_c2r(as_plan(plan_inv_), as_fc(c2_), rout_);
  store(rout_, oy);
}

}  // namespace railsim::contact::mim
