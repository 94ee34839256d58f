// Text clouds with a header line: columns found by name, the separator of
// the file (comma, semicolon, tab or spaces), decimal commas where ';' or tab
// separates, and clear refusals of what cannot be read one way only
// (docs/cli.md, "Text clouds").
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "cloud/cloud_reader.hpp"
#include "cloud_test_support.hpp"

namespace {

std::vector<double> parsed(const std::string& text) {
  std::vector<double> xyz;
  std::string error;
  CAPTURE(text);
  CHECK_MESSAGE(spinhash::host::test::try_read_cloud_bytes(text, &xyz, &error), error);
  return xyz;
}

void check_refused(const std::string& text, const std::string& words) {
  std::vector<double> xyz = {1.0};
  std::string error;
  CAPTURE(text);
  CHECK_FALSE(spinhash::host::test::try_read_cloud_bytes(text, &xyz, &error));
  CHECK(xyz.empty());
  CHECK_MESSAGE(error.find(words) != std::string::npos, error);
}

const std::vector<double> kTwoPoints = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};

}  // namespace

TEST_CASE("text clouds: x y z found by the header's column names, not by position") {
  CHECK(parsed("id,x,y,z,intensity\n7,1,2,3,99\n8,4,5,6,98\n") == kTwoPoints);
  CHECK(parsed("X Y Z\n1 2 3\n4 5 6\n") == kTwoPoints);
  CHECK(parsed("intensity\tz\ty\tx\n9\t3\t2\t1\n9\t6\t5\t4\n") == kTwoPoints);
  CHECK(parsed("//X,Y,Z,R,G,B\n1,2,3,0,0,0\n4,5,6,0,0,0\n") == kTwoPoints);  // CloudCompare's header
  CHECK(parsed("# exported\n\nid;x;y;z\n1;1;2;3\n# a comment line\n2;4;5;6 # trailing\n") == kTwoPoints);
  CHECK(parsed(" x , y , z \n 1 , 2 , 3 \n4,5,6\r\n") == kTwoPoints);
  // No header: the first three columns.
  CHECK(parsed("1 2 3 0.5\n4 5 6 0.5\n") == kTwoPoints);
  CHECK(parsed("1;2;3\n4;5;6\n") == kTwoPoints);
}

TEST_CASE("text clouds: decimal commas where ';' or tab separates the values") {
  CHECK(parsed("1,5;2,5;3,5\n") == std::vector<double>{1.5, 2.5, 3.5});
  CHECK(parsed("x;y;z\n431000,25;4020000,5;85,125\n") == std::vector<double>{431000.25, 4020000.5, 85.125});
  CHECK(parsed("x\ty\tz\n-1,5\t2,25\t3\n") == std::vector<double>{-1.5, 2.25, 3.0});
  CHECK(parsed("1.5;2.5;3.5\n") == std::vector<double>{1.5, 2.5, 3.5});  // points still work
}

TEST_CASE("text clouds: what could be read two ways is refused with a clear message") {
  // Commas and spaces both between values: decimal commas or separators?
  check_refused("1,5 2,5 3,5\n", "ambiguous");
  check_refused("x,y,z\n1,5 2,5 3,5\n", "ambiguous");
  check_refused("x y z\n1,5 2,5 3,5\n", "decimal commas are read only where");  // spaces: '.' only
  check_refused("1.000,5;2;3\n", "decimal");         // a point and a comma in one number
  check_refused("a,b,c\n1,2,3\n", "no x, y and z");  // a header without the coordinates
  check_refused("id,x,y\n1,2,3\n", "no x, y and z");
  check_refused("x,y,z,x\n1,2,3,4\n", "twice");
  check_refused("x;y;z\n1;2\n", "line 2");  // a short row names its line
  check_refused("x,y,z\n1,2,three\n", "not a number");
}
