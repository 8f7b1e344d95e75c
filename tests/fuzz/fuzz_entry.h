// The fuzz entry points, shared by the libFuzzer targets (tests/fuzz/*.cpp)
// and tests/programs/fuzz_regression_test.cpp, which replays every saved finding and
// seed through the same functions. Each takes arbitrary bytes, treats
// InputError (and CLI::Error) as the expected answer to bad input, and lets
// anything else escape; a broken promise calls fuzzCheckFailed().
//
// Define ALIASLAB_FUZZ_NO_MAIN before including the target sources to get
// the functions without LLVMFuzzerTestOneInput (the regression test does).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace aliaslab::fuzz {

/// A broken promise: abort under libFuzzer (a finding), throw in the regression test.
[[noreturn]] inline void fuzzCheckFailed(const char* what) {
#ifdef ALIASLAB_FUZZ_NO_MAIN
  throw std::logic_error(std::string("fuzz check failed: ") + what);
#else
  (void)what;
  std::abort();
#endif
}
#define ALIASLAB_FUZZ_CHECK(cond) ((cond) ? void(0) : ::aliaslab::fuzz::fuzzCheckFailed(#cond))

/// A target's libFuzzer entry point, calling `fn` on each input (none under ALIASLAB_FUZZ_NO_MAIN).
#ifdef ALIASLAB_FUZZ_NO_MAIN
#define ALIASLAB_FUZZ_TARGET(fn)
#else
#define ALIASLAB_FUZZ_TARGET(fn)                                            \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    fn(data, size);                                                         \
    return 0;                                                               \
  }
#endif

/// A per-process file or folder under /dev/shm (a target's static), removed when the process ends.
struct ScratchPath {
  std::string path;
  ~ScratchPath() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

void fuzzScene(const uint8_t* data, size_t size);  ///< parseSceneText; meshes resolve in scenes/
void fuzzObj(const uint8_t* data, size_t size);    ///< loadObj on the bytes as a file in /dev/shm
void fuzzCli(const uint8_t* data, size_t size);    ///< raytracer options, sampler/filter factories

/// Reads fixed-size values from the front of the fuzz input (zeros when it runs out).
class FuzzInput {
 public:
  FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  size_t remaining() const { return size_ - pos_; }
  uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool flag() { return byte() & 1; }
  template <class T>
  T raw() {
    T v{};
    unsigned char* p = reinterpret_cast<unsigned char*>(&v);
    for (size_t i = 0; i < sizeof(T); ++i) p[i] = byte();
    return v;
  }
  /// A whole number in [lo, hi].
  long long range(long long lo, long long hi) {
    const unsigned long long span = static_cast<unsigned long long>(hi - lo) + 1;
    const unsigned long long v = raw<uint32_t>();
    return lo + static_cast<long long>(span ? v % span : v);
  }
  /// A float in [lo, hi].
  float unit(float lo, float hi) { return lo + (hi - lo) * (raw<uint16_t>() / 65535.f); }
  /// Up to `max` characters, ended early by a NUL byte.
  std::string text(size_t max) {
    std::string s;
    while (s.size() < max && remaining() > 0) {
      const char c = static_cast<char>(byte());
      if (c == '\0') break;
      s += c;
    }
    return s;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace aliaslab::fuzz
