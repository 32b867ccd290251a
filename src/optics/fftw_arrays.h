// What every user of FFTW here shares: arrays in FFTW's aligned memory, freed by FFTW, and
// the one lock around its planner (plans may be made and destroyed by one thread at a time;
// executing them is thread-safe).
#pragma once
#include <fftw3.h>

#include <memory>
#include <mutex>
#include <new>

namespace objektiv {

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

template <class T>
std::unique_ptr<T[], FftwFree> FftwArray(size_t n) {
  auto p = std::unique_ptr<T[], FftwFree>(static_cast<T*>(fftw_malloc(sizeof(T) * n)));
  if (!p) throw std::bad_alloc();
  return p;
}

std::mutex& FftwPlannerMutex();

// The smallest power of two >= v (a grid size for the FFTs).
inline int NextPowerOfTwo(double v) {
  int n = 1;
  while (n < v) n *= 2;
  return n;
}

}  // namespace objektiv
