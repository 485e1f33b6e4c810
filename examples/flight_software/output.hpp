// Where the flight example's lines go, and the little formatting it needs without printf: the
// platform provides flight_write_line (host_output.cpp: stdout; on the Cortex-M7 of tests/flight:
// semihosting).
#pragma once

#include <cstddef>

/// Writes one line of text (without its newline).
extern "C" void flight_write_line(const char* text);

/// A line built in a fixed buffer: text, integers and reals appended, never overrun.
class line {
 public:
  line& operator<<(const char* s) {
    while (*s && length_ + 1 < sizeof text_) text_[length_++] = *s++;
    text_[length_] = '\0';
    return *this;
  }
  line& operator<<(int n) {
    char digits[12];
    int count = 0;
    unsigned u = n < 0 ? 0u - static_cast<unsigned>(n) : static_cast<unsigned>(n);
    do {
      digits[count++] = static_cast<char>('0' + u % 10);
      u /= 10;
    } while (u);
    if (n < 0) *this << "-";
    char s[2] = {0, 0};
    while (count) {
      s[0] = digits[--count];
      *this << s;
    }
    return *this;
  }
  /// x in scientific notation with 3 decimals (1.234e-05), or nan.
  line& scientific(float x) {
    if (x != x) return *this << "nan";
    if (x < 0) {
      *this << "-";
      x = -x;
    }
    int exponent = 0;
    while (x >= 10.f) {
      x /= 10.f;
      ++exponent;
    }
    while (x > 0.f && x < 1.f) {
      x *= 10.f;
      --exponent;
    }
    int digits = static_cast<int>(x * 1000.f + 0.5f);
    if (digits >= 10000) {
      digits /= 10;
      ++exponent;
    }
    *this << digits / 1000 << ".";
    const int rest = digits % 1000;
    if (rest < 100) *this << "0";
    if (rest < 10) *this << "0";
    *this << rest << "e" << (exponent < 0 ? "-" : "+");
    const int e = exponent < 0 ? -exponent : exponent;
    if (e < 10) *this << "0";
    return *this << e;
  }
  void write() const { flight_write_line(text_); }

 private:
  char text_[160] = {};
  std::size_t length_ = 0;
};
