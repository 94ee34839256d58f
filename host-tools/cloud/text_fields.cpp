#include "cloud/text_fields.hpp"

#include <charconv>
#include <cstddef>

namespace spinhash::host::text {
namespace {

constexpr std::size_t kMaxQuotedChars = 40;  // of a bad token, in messages

bool is_space(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool decimal_commas(Separator s) { return s == Separator::kSemicolon || s == Separator::kTab; }

std::string quoted(std::string_view token) {
  return "'" + std::string(token.substr(0, kMaxQuotedChars)) + "'";
}

}  // namespace

Separator choose_separator(std::string_view first_line) {
  if (first_line.find(';') != std::string_view::npos) return Separator::kSemicolon;
  if (first_line.find('\t') != std::string_view::npos) return Separator::kTab;
  if (first_line.find(',') != std::string_view::npos) return Separator::kComma;
  return Separator::kSpaces;
}

const char* separator_name(Separator s) {
  switch (s) {
    case Separator::kComma: return "','";
    case Separator::kSemicolon: return "';'";
    case Separator::kTab: return "tab";
    default: return "spaces";
  }
}

bool split_fields(std::string_view line, Separator s, std::vector<std::string_view>* fields,
                  std::string* error) {
  fields->clear();
  line = trimmed(line);
  if (s == Separator::kSpaces) {
    for (std::size_t pos = 0; pos < line.size();) {
      while (pos < line.size() && is_space(line[pos])) ++pos;
      const std::size_t start = pos;
      while (pos < line.size() && !is_space(line[pos])) ++pos;
      if (pos > start) fields->push_back(line.substr(start, pos - start));
    }
    return true;
  }
  const char sep = static_cast<char>(s);
  for (std::size_t start = 0;;) {
    const std::size_t end = line.find(sep, start);
    const std::string_view field =
        trimmed(line.substr(start, end == std::string_view::npos ? end : end - start));
    if (s == Separator::kComma && field.find_first_of(" \t") != std::string_view::npos) {
      if (error)
        *error = "ambiguous: commas and spaces both between values in " + quoted(line) +
                 " (decimal commas need ';' or tab between values)";
      return false;
    }
    fields->push_back(field);
    if (end == std::string_view::npos) return true;
    start = end + 1;
  }
}

bool parse_field(std::string_view field, Separator s, double* value, std::string* error) {
  std::string buffer;
  const std::size_t comma = field.find(',');
  if (comma != std::string_view::npos && decimal_commas(s)) {
    if (field.find_first_of(".,", comma + 1) != std::string_view::npos || field.find('.') < comma) {
      if (error)
        *error = "not one decimal number: " + quoted(field) + " (a decimal comma and a '.' or a second ',')";
      return false;
    }
    buffer.assign(field);
    buffer[comma] = '.';
    field = buffer;
  }
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  const char* end = field.data() + field.size();
  const auto result = std::from_chars(field.data(), end, *value);
  if (field.empty() || result.ec != std::errc() || result.ptr != end) {
    if (error)
      *error = "not a number: " + quoted(field) +
               (field.find(',') != std::string_view::npos
                    ? " (decimal commas are read only where ';' or tab separates)"
                    : "");
    return false;
  }
  return true;
}

}  // namespace spinhash::host::text
