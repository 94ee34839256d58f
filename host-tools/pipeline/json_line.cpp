#include "pipeline/json_line.hpp"

#include <cmath>
#include <cstdio>

#include "pipeline/version.hpp"

namespace spinhash::pipeline {
namespace {

constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

bool continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Length of the valid UTF-8 sequence at s[i] (RFC 3629: no overlongs, no
// surrogates, nothing above U+10FFFF), or 0.
size_t utf8_length(const std::string& s, size_t i) {
  const auto at = [&s](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = at(i);
  size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    lo = c == 0xE0 ? 0xA0 : 0x80;
    hi = c == 0xED ? 0x9F : 0xBF;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    lo = c == 0xF0 ? 0x90 : 0x80;
    hi = c == 0xF4 ? 0x8F : 0xBF;
  } else {
    return 0;
  }
  if (i + n > s.size() || at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (!continuation(at(i + k))) return 0;
  return n;
}

}  // namespace

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      const size_t n = utf8_length(s, i);
      out += n == 0 ? std::string(kReplacement) : s.substr(i, n);
      i += n == 0 ? 1 : n;
      continue;
    }
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
    ++i;
  }
  return out + "\"";
}

std::string json_number(double v, int digits) {
  if (!std::isfinite(v)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string json_member(const char* key, const std::string& raw_value) {
  return json_string(key) + ":" + raw_value;
}

std::string json_object(std::initializer_list<std::string> members) {
  std::string s = "{";
  for (const std::string& m : members) s += (s.size() > 1 ? "," : "") + m;
  return s + "}";
}

std::string json_array(const std::vector<std::string>& raw_values) {
  std::string s = "[";
  for (const std::string& v : raw_values) s += (s.size() > 1 ? "," : "") + v;
  return s + "]";
}

std::string json_version_member() { return "\"version\":" + json_string(version()); }

std::string unreadable_json(const char* key, const std::string& name, const std::string& error) {
  return json_object({json_member(key, json_string(name)), json_member("status", json_string("unreadable")),
                      json_member("error", json_string(error)), json_member("ranking", "[]"),
                      json_member("pose", "null"), json_version_member()});
}

}  // namespace spinhash::pipeline
