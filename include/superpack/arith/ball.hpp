// Multi-precision intervals: an RAII wrapper around Arb's arb_t (midpoint-radius balls).
// Each Ball carries the working precision it was made with; a binary operation works at the
// larger of its operands' precisions, so precision is explicit at creation and never global.
#pragma once
#include <arb.h>

namespace superpack {

class Ball {
public:
    explicit Ball(slong precision);
    Ball(const Ball& other);
    Ball(Ball&& other) noexcept;
    Ball& operator=(const Ball& other);
    Ball& operator=(Ball&& other) noexcept;
    ~Ball();

    arb_ptr get() { return value_; }
    arb_srcptr get() const { return value_; }
    slong precision() const { return precision_; }

private:
    arb_t value_;
    slong precision_;
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
