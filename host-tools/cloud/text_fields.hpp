// The fields of one line of a text point cloud: the file's separator (chosen
// once, from its first line), fields split and trimmed, numbers read with a
// decimal point, or a decimal comma where ';' or tab separates the values.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace spinhash::host::text {

enum class Separator : char { kSpaces = ' ', kComma = ',', kSemicolon = ';', kTab = '\t' };

// ';' if the line holds one, else tab, else ',', else runs of spaces.
Separator choose_separator(std::string_view first_line);
const char* separator_name(Separator s);

// The line's fields, whitespace around each trimmed. False with *error when
// the line cannot be split one way only (commas and spaces both between values).
bool split_fields(std::string_view line, Separator s, std::vector<std::string_view>* fields,
                  std::string* error);

// A decimal number ("+1.5", "-2e3", "nan"; "1,5" where decimal commas apply).
// False with *error naming the token when it is not one.
bool parse_field(std::string_view field, Separator s, double* value, std::string* error);

}  // namespace spinhash::host::text
