// A count in a message, with its noun in agreement ("1 vertex", "2 vertices"): every message the
// library writes with a count says it this way.
#pragma once

#include <cstddef>
#include <string>

namespace kergen {

inline std::string count_of(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The verb of a count's sentence: "is" / "are", "was" / "were", "belongs" / "belong".
inline const char* verb_for(size_t n, const char* one, const char* many) { return n == 1 ? one : many; }

}  // namespace kergen
