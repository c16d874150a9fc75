// Names of labels: the "label name" tables of atlases (tabs, CR/LF,
// comments), the rules for a name, and label lists written with names
// (names replaced by labels; labels, ranges, '*' and a lone value kept; an
// unknown name an error with the nearest known one).
#include <restshape/base/label_names.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "checks.h"

using namespace RestShape;
using namespace checks;

namespace
{
  LabelNames
  table(const std::string &text)
  {
    const std::string file = "label_names_test.txt";
    std::ofstream(file) << text;
    try
      {
        LabelNames names = read_label_names(file, "--label-names");
        std::remove(file.c_str());
        return names;
      }
    catch (...)
      {
        std::remove(file.c_str());
        throw;
      }
  }
} // namespace

int
main()
{
  const LabelNames aal =
    table("# atlas\r\n1 Precentral_L 2001\r\n\r\n2\tPrecentral_R\t2002\r\n"
          "2035 3rd_ventricle\n");
  expect(aal.name(1) == "Precentral_L" && aal.name(2) == "Precentral_R" &&
           aal.name(2035) == "3rd_ventricle" && aal.name(3).empty(),
         "a .nii.txt table: blanks, tabs, CR/LF, comments, extra columns");
  expect(aal.find("Precentral_R") == Label(2) && !aal.find("Precentral"),
         "names are found whole");

  expect(error_of([] { table("1 a\nx b\n"); }).find("line 2: expected") == 0,
         "a line without a label is an error naming the line");
  expect(error_of([] { table("1 a\n2 a\n"); }) ==
           "line 2: 'a' names both label 1 and label 2; expected one label "
           "per name",
         "a name of two labels is an error");
  expect(error_of([] { table("1 123\n"); }).find("'123' cannot name") !=
           std::string::npos,
         "a name without a letter is refused");
  expect(error_of([] { table("# only a comment\n"); }).find("names no label") !=
           std::string::npos,
         "a table without names is an error");
  expect(!LabelNames::is_valid_name("a:b") &&
           !LabelNames::is_valid_name("a,b") &&
           !LabelNames::is_valid_name("a b") &&
           LabelNames::is_valid_name("G_Frontal_Sup-1"),
         "names cannot hold a label list's syntax");

  LabelNames tissues;
  tissues.add(1, "cerebrum", "", "");
  tissues.add(3, "cerebellum", "", "");
  const auto replaced = [&](const std::string &text, const bool values) {
    return replace_label_names(text, "Some/List", tissues, values);
  };
  expect(replaced("cerebrum:1500, 4-9:3, *:1000", true) ==
           "1:1500, 4-9:3, *:1000",
         "a value list with a name, a range and a default");
  expect(replaced("1200", true) == "1200", "a lone value stays a value");
  expect(replaced("cerebellum, 5:xy, cerebrum:z", false) == "3, 5:xy, 1:z",
         "fixed labels with names and components");
  const std::string unknown = error_of([&] { replaced("cerebelum:2", true); });
  std::cout << unknown << std::endl;
  expect(unknown.find("'cerebelum' is neither a label nor a tissue name of "
                      "the mesh; did you mean 'cerebellum'") == 0 &&
           unknown.find("(names: cerebrum (1), cerebellum (3))") !=
             std::string::npos,
         "an unknown name is an error with the nearest and the known names");
  expect(replace_label_names("abc:1", "Some/List", LabelNames(), true) ==
           "abc:1",
         "without names the text is left to the label parser");
  return failures == 0 ? 0 : 1;
}
