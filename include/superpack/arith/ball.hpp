// Multi-precision intervals: an RAII wrapper around Arb's arb_t (midpoint-radius balls).
// Each Ball carries the working precision it was made with; a binary operation works at the
// larger of its operands' precisions, so precision is explicit at creation and never global.
//
// The arb_t lives in opaque storage so that this header, included by every formula, does not
// pull Arb (and FLINT, GMP, MPFR) into every translation unit; src/arith/ball.cpp checks the
// size and alignment, and arith/arb_access.hpp gives the arb_t to the code that calls Arb.
#pragma once

namespace superpack {

class Ball {
public:
    explicit Ball(long precision);
    Ball(const Ball& other);
    Ball(Ball&& other) noexcept;
    Ball& operator=(const Ball& other);
    Ball& operator=(Ball&& other) noexcept;
    ~Ball();

    long precision() const { return precision_; }
    void* storage() { return storage_; }
    const void* storage() const { return storage_; }

    static constexpr unsigned long storage_size = 48;  // sizeof(arb_struct) on LP64
    static constexpr unsigned long storage_alignment = 8;

private:
    alignas(storage_alignment) unsigned char storage_[storage_size];
    long precision_;
};

Ball operator+(const Ball& a, const Ball& b);
Ball operator-(const Ball& a, const Ball& b);
Ball operator*(const Ball& a, const Ball& b);
Ball operator/(const Ball& a, const Ball& b);
Ball operator-(const Ball& a);
Ball operator+(const Ball& a, long n);
Ball operator-(const Ball& a, long n);
Ball operator-(long n, const Ball& a);
Ball operator*(long n, const Ball& a);
Ball operator*(const Ball& a, long n);
Ball operator/(const Ball& a, long n);
Ball operator/(long n, const Ball& a);
inline Ball operator+(long n, const Ball& a) { return a + n; }
Ball& operator+=(Ball& a, const Ball& b);
Ball& operator-=(Ball& a, const Ball& b);
Ball& operator*=(Ball& a, const Ball& b);

}  // namespace superpack
