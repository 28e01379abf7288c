#pragma once
// Subnormal floats flushed to zero (x86's FTZ and DAZ) in the calling thread while one of these
// lives; the instance and device builders hold one. lavapipe runs compute shaders on worker
// threads that it starts while its instance and device are made, which inherit the
// floating-point environment of the thread making them, and (unlike its rasteriser threads)
// it leaves subnormals on there: every subnormal operand or result then costs the CPU a
// microcode assist of a hundred cycles or more. Near-neutral colours, small lobe energies and
// the tails of CIEDE2000's Gaussian made that a sixth of the grid's evaluation. Vulkan lets
// 32-bit subnormals be flushed unless a shader asks to preserve them (ours do not); the
// caller's own environment is restored, so CPU code keeps IEEE behaviour.
#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

namespace matevo::gpu {

class SubnormalsFlushed {
public:
#if defined(__x86_64__) || defined(__i386__)
    SubnormalsFlushed() : saved_(_mm_getcsr()) {
        _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
    }
    ~SubnormalsFlushed() { _mm_setcsr(saved_); }
    SubnormalsFlushed(const SubnormalsFlushed&) = delete;
    SubnormalsFlushed& operator=(const SubnormalsFlushed&) = delete;

private:
    static constexpr unsigned kFlushToZero = 0x8000;
    static constexpr unsigned kDenormalsAreZero = 0x0040;
    unsigned saved_;
#endif
};

}  // namespace matevo::gpu
