// numbers.h — exact number parsing for the text readers, private to io/: a decimal token to the
// double it denotes (correctly rounded, locale-independent, non-finite values told apart from
// garbage) and a token to an integer without overflow. parse_double's fast path, parse_integer
// and read_coordinates run per token and are inline; the checked slow path is in numbers.cpp.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>
#if defined(__has_include)
#if __has_include(<version>)
#include <version>
#endif
#endif

#include "io/reader.h"
#include "io/text_scan.h"

// libstdc++ (g++ >= 11) has a correctly rounded, locale-independent std::from_chars for double.
// Emscripten's libc++ deletes that overload; there we use strtod, which in its musl-based libc
// ignores the locale (the decimal point is always '.').
#if defined(__cpp_lib_to_chars) && defined(__GLIBCXX__)
#define KERGEN_FROM_CHARS_DOUBLE 1
#else
#define KERGEN_FROM_CHARS_DOUBLE 0
#endif

namespace kergen::io {

enum class NumberStatus { Ok, Invalid, NonFinite };

// Strict decimal syntax: [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. "inf" and "nan"
// spellings are recognised so they can be reported as non-finite rather than as garbage.
NumberStatus parse_double_checked(std::string_view token, double& out);

// parse_double_checked, with a fast path for the usual token: without a leading '+', the strings
// std::from_chars reads in full as a finite number are exactly those of the strict syntax above
// (its general format is [-] (digits [. digits] | . digits) [(e|E) [+-] digits], or inf / nan
// spellings, which are not finite), and parse_double_checked converts them with the same call.
// Anything else (a '+', a partial read, out of range, non-finite) goes the checked way.
inline NumberStatus parse_double(std::string_view token, double& out) {
#if KERGEN_FROM_CHARS_DOUBLE
  if (!token.empty() && token[0] != '+') {
    double value;
    const auto converted = std::from_chars(token.data(), token.data() + token.size(), value);
    if (converted.ec == std::errc() && converted.ptr == token.data() + token.size() && std::isfinite(value)) {
      out = value;
      return NumberStatus::Ok;
    }
  }
#endif
  return parse_double_checked(token, out);
}

// [+-]digits, no overflow.
inline bool parse_integer(std::string_view token, long long& out) {
  // The usual token, 1 to 9 digits, cannot overflow: read directly.
  if (!token.empty() && token.size() <= 9) {
    long long value = 0;
    size_t i = 0;
    for (; i < token.size() && token[i] >= '0' && token[i] <= '9'; ++i) value = value * 10 + (token[i] - '0');
    if (i == token.size()) {
      out = value;
      return true;
    }
  }
  if (!token.empty() && token[0] == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token[0] == '-') return false;
  }
  if (token.empty()) return false;
  auto converted = std::from_chars(token.data(), token.data() + token.size(), out);
  return converted.ec == std::errc() && converted.ptr == token.data() + token.size();
}

// Reads three coordinates; reports a bad or non-finite one with the line number.
inline void read_coordinates(Tokens& tokens, double xyz[3], const std::string& name, size_t line, const char* what) {
  for (int k = 0; k < 3; ++k) {
    std::string_view token;
    if (!tokens.next(token))
      fail_at_line(name, line, std::string(what) + " needs 3 coordinates, found " + std::to_string(k));
    switch (parse_double(token, xyz[k])) {
      case NumberStatus::Ok: break;
      case NumberStatus::Invalid: fail_at_line(name, line, "invalid number " + quoted(token));
      case NumberStatus::NonFinite: fail_at_line(name, line, "non-finite coordinate " + quoted(token));
    }
  }
}

}  // namespace kergen::io
