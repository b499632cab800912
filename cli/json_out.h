// json_out.h — JSON text for the CLI's --json output (kergen_cli.cpp, cells.cpp): strings escaped,
// numbers with 17 significant digits (they read back exactly), non-finite numbers as null.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

inline std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);  // UTF-8 passes through (file names may be non-ASCII)
        }
    }
  }
  return out + "\"";
}

// %.17g round-trips; JSON has no NaN or infinity, so those become null.
inline std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}
