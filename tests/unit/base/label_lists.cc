// Label lists of the parameters: ranges ("1-90:1500"), a default
// ("*:1500"), fixed labels with ranges, and the check against the mesh's
// labels (a single label must exist, a range must hold one); the shortened
// text of long label lists.
#include <restshape/base/label_values.h>

#include <iostream>
#include <string>

#include "checks.h"

using namespace RestShape;
using namespace checks;

int
main()
{
  const std::string E = "Materials/Young's modulus";
  const LabelValues v = LabelValues::parse("1-90:1500, 95:3000, *:2000", E);
  expect(v(1) == 1500 && v(90) == 1500, "range 1-90 gives 1500 to 1 and 90");
  expect(v(95) == 3000, "single label 95 gives 3000");
  expect(v(91) == 2000 && v(200) == 2000, "the default gives 2000 to others");
  expect(LabelValues::parse("1200", E)(7) == 1200, "a single value for all");
  expect(error_of([&] { LabelValues::parse("1-3:1, 3:2", E); }) ==
           "label 3 is given twice",
         "a label in a range and again is an error");
  expect(error_of([&] { LabelValues::parse("1:1, *:2, *:3", E); }) ==
           "the default '*' is given twice",
         "two defaults are an error");
  expect(error_of([&] { LabelValues::parse("5-2:1", E); }).find("upwards") !=
           std::string::npos,
         "a downward range is an error");
  expect(error_of([&] {
           LabelValues::parse("1:1", E)(2);
         }).find("no value for label 2") != std::string::npos,
         "a label without a value and without a default is an error");

  const std::vector<FixedLabel> fixed =
    parse_fixed_labels("3, 7-9:xy", "Boundary conditions/Fixed labels");
  expect(fixed.size() == 4 && fixed[1].label == 7 && fixed[3].label == 9 &&
           fixed[3].components[0] && !fixed[3].components[2],
         "fixed labels '3, 7-9:xy' give 3, 7, 8, 9, the range in x and y");
  expect(parse_label_set("1, 4-6", "Loads/Pressure labels") ==
           std::set<Label>{1, 4, 5, 6},
         "label set '1, 4-6'");

  const std::set<Label> mesh = {1, 2, 3, 10};
  const auto check           = [&](const std::string &text, const bool values) {
    return error_of([&] {
      check_labels_exist({"Some/List", text, values}, mesh);
    });
  };
  expect(check("1-2:5, 3:6, *:1", true).empty(), "known labels pass");
  expect(check("4-12:5", true).empty(), "a range holding label 10 passes");
  expect(check("7", true).empty(), "a single value for all passes");
  expect(check("1:5, 7:6", true) ==
           "label 7 is not a label of the mesh (labels: 1-3, 10)",
         "an unknown label in a value list is an error");
  expect(check("4-9", false) ==
           "no label in 4-9 is a label of the mesh (labels: 1-3, 10)",
         "a range without a label of the mesh is an error");
  expect(check("7:xy", false).find("label 7 is not") != std::string::npos,
         "an unknown fixed label is an error");

  std::set<Label> many;
  for (Label l = 1; l <= 192; l += 2)
    many.insert(l);
  const std::string text = to_string(many);
  std::cout << "96 odd labels: " << text << std::endl;
  expect(text.size() < 80 && text.find("(96 labels)") != std::string::npos &&
           text.substr(text.size() - 3) == "191",
         "a long label list is shortened, with the count and the last");
  expect(to_string({1, 2, 3, 4, 7, 8}) == "1-4, 7, 8", "runs become ranges");
  return failures == 0 ? 0 : 1;
}
