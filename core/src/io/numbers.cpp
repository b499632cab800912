// numbers.cpp — parse_double_checked: the strict decimal syntax, converted exactly by from_chars
// (libstdc++) or strtod (Emscripten), overflow told from underflow (numbers.h).
#include "io/numbers.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace kergen::io {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Decimal exponent of the leading significant digit of a syntactically valid decimal number with
// at least one non-zero digit; used only to tell overflow from underflow.
long long leading_decimal_exponent(std::string_view mantissa, long long exponent) {
  long long position = -1;  // exponent of the next digit relative to the decimal point
  size_t point = mantissa.find('.');
  size_t integer_digits = point == std::string_view::npos ? mantissa.size() : point;
  position = static_cast<long long>(integer_digits) - 1;
  for (char c : mantissa) {
    if (c == '.') continue;
    if (c != '0') return position + exponent;
    --position;
  }
  return std::numeric_limits<long long>::min();
}

}  // namespace

NumberStatus parse_double_checked(std::string_view token, double& out) {
  size_t i = 0, n = token.size();
  bool negative = false;
  if (i < n && (token[i] == '+' || token[i] == '-')) negative = token[i++] == '-';
  std::string_view unsigned_part = token.substr(i);
  if (!unsigned_part.empty() && !is_digit(unsigned_part[0]) && unsigned_part[0] != '.') {
    const bool nan_with_payload = unsigned_part.size() > 4 && equals_ignore_case(unsigned_part.substr(0, 4), "nan(") &&
                                  unsigned_part.back() == ')';
    if (equals_ignore_case(unsigned_part, "inf") || equals_ignore_case(unsigned_part, "infinity") ||
        equals_ignore_case(unsigned_part, "nan") || nan_with_payload)
      return NumberStatus::NonFinite;
    return NumberStatus::Invalid;
  }
  size_t mantissa_begin = i, digits = 0;
  while (i < n && is_digit(token[i])) ++i, ++digits;
  if (i < n && token[i] == '.') {
    ++i;
    while (i < n && is_digit(token[i])) ++i, ++digits;
  }
  if (digits == 0) return NumberStatus::Invalid;
  std::string_view mantissa = token.substr(mantissa_begin, i - mantissa_begin);
  long long exponent = 0;
  if (i < n && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    bool exponent_negative = false;
    if (i < n && (token[i] == '+' || token[i] == '-')) exponent_negative = token[i++] == '-';
    size_t exponent_digits = 0;
    while (i < n && is_digit(token[i])) {
      if (exponent < 1'000'000'000) exponent = exponent * 10 + (token[i] - '0');
      ++i, ++exponent_digits;
    }
    if (exponent_digits == 0) return NumberStatus::Invalid;
    if (exponent_negative) exponent = -exponent;
  }
  if (i != n) return NumberStatus::Invalid;

  // Hand the validated text (without a leading '+', which from_chars refuses) to the converter.
  std::string_view number = token.substr(token[0] == '+' ? 1 : 0);
  double value = 0;
  bool out_of_range = false;
#if KERGEN_FROM_CHARS_DOUBLE
  auto converted = std::from_chars(number.data(), number.data() + number.size(), value);
  if (converted.ec == std::errc::result_out_of_range)
    out_of_range = true;
  else if (converted.ec != std::errc() || converted.ptr != number.data() + number.size())
    return NumberStatus::Invalid;
#else
  char small[64];
  std::string large;
  const char* text;
  if (number.size() < sizeof small) {
    std::memcpy(small, number.data(), number.size());
    small[number.size()] = '\0';
    text = small;
  } else {
    large.assign(number);
    text = large.c_str();
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text, &end);
  if (end != text + number.size()) return NumberStatus::Invalid;
  if (errno == ERANGE || std::isinf(value)) out_of_range = true;
#endif
  if (out_of_range) {
    // Too large for a double is a non-finite coordinate; too small rounds to a signed zero.
    if (leading_decimal_exponent(mantissa, exponent) > 0) return NumberStatus::NonFinite;
    if (value == 0 || std::isinf(value)) value = negative ? -0.0 : 0.0;
  }
  if (!std::isfinite(value)) return NumberStatus::NonFinite;
  out = value;
  return NumberStatus::Ok;
}

}  // namespace kergen::io
