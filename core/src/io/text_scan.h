// text_scan.h — the text readers' line and token scanning (OFF, OBJ, ASCII STL, ASCII PLY, and
// detection's first keyword), private to io/. Everything here runs per line or per token, so it is
// inline: each reader keeps the speed it had when the readers were one translation unit.
#pragma once

#include <cstddef>
#include <cstring>
#include <string_view>

namespace kergen::io {

// ' ', '\t', '\r', '\v' or '\f' (not '\n'). Every byte above ' ' (most of a token's) is answered by
// the first comparison.
inline bool is_blank(char c) {
  const unsigned char u = static_cast<unsigned char>(c);
  return u <= ' ' && (u == ' ' || (u >= '\t' && u <= '\r' && u != '\n'));
}

class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const char* begin = text_.data() + pos_;
    const void* newline = std::memchr(begin, '\n', text_.size() - pos_);
    size_t end = newline ? static_cast<size_t>(static_cast<const char*>(newline) - text_.data()) : text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_number_;
    return true;
  }
  size_t line_number() const { return line_number_; }
  size_t remaining_bytes() const { return pos_ >= text_.size() ? 0 : text_.size() - pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_number_ = 0;
};

class Tokens {
 public:
  explicit Tokens(std::string_view line) : line_(line) {}
  bool next(std::string_view& token) {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    if (pos_ >= line_.size()) return false;
    size_t start = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_])) ++pos_;
    token = line_.substr(start, pos_ - start);
    return true;
  }
  bool at_end() {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    return pos_ >= line_.size();
  }

 private:
  std::string_view line_;
  size_t pos_ = 0;
};

inline std::string_view strip_comment(std::string_view line) {
  size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

inline bool equals_ignore_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

inline bool only_blank(std::string_view text) {
  for (char c : text)
    if (!is_blank(c) && c != '\n') return false;
  return true;
}

}  // namespace kergen::io
