// Plain-text point clouds (docs/cli.md, "Text clouds"): one point per line;
// '#' starts a comment; blank lines skipped. The first line fixes the
// separator of the whole file (';', tab, ',' or spaces, in that order of
// precedence); a decimal comma is read only where ';' or tab separates. A
// first line with no number in it is a header: x, y and z are the columns
// named so (any case; CloudCompare's leading "//" allowed), other columns
// ignored. Without a header, the first three columns are x y z.
#pragma once

#include <string>
#include <vector>

namespace spinhash::host {

bool read_text_cloud(const std::string& text, std::vector<double>* xyz, std::string* error);

}  // namespace spinhash::host
