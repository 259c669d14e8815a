// Tests of contact/reduction.cpp: every form of the reduction syntax, lists,
// errors that name the option and the allowed range, and the naming rule (a
// preset name only when the user chose the preset).
#include <catch2/catch.hpp>

#include "contact/reduction.hpp"
#include "core/errors.hpp"

using namespace railsim::contact;

TEST_CASE("reduction entries keep the form the user gave", "[reduction]") {
  const ReductionSpec fe = parse_reduction_spec("elastic_fe", "--reduction");
  CHECK(fe.form == ReductionForm::preset);
  CHECK(fe.k.k11 == 0.72);
  CHECK(fe.k.k22 == 0.56);
  CHECK(fe.k.k23 == 0.56);
  CHECK(reduction_label(fe) == "elastic_fe");
  // The same numbers given as numbers stay numbers.
  const ReductionSpec nums = parse_reduction_spec("0.72,0.56,0.56", "--reduction");
  CHECK(nums.form == ReductionForm::factors);
  CHECK(reduction_label(nums) == "0.72,0.56,0.56");
  const ReductionSpec half = parse_reduction_spec(" 0.5 ", "--reduction");
  CHECK(half.form == ReductionForm::uniform);
  CHECK(half.k.k22 == 0.5);
  CHECK(reduction_label(half) == "uniform 0.5");  // not "third_body"
  CHECK(reduction_label(parse_reduction_spec("third_body", "x")) == "third_body");
  CHECK(describe_reduction({0.5, 0.5, 0.5}) == "uniform 0.5");
  CHECK(describe_reduction({0.72, 0.56, 0.56}) == "0.72,0.56,0.56");
  CHECK(describe_reduction({1, 1, 1}) == "uniform 1");
  CHECK(parse_reduction_spec("(0.6,0.5,0.4)", "x").k.k23 == 0.4);
  CHECK(parse_reduction_spec("[0.6,0.5,0.4]", "x").form == ReductionForm::factors);
}

TEST_CASE("a third-body layer is parsed with its parameters and needs a patch", "[reduction]") {
  const ReductionSpec l = parse_reduction_spec("layer:h=125e-6,G3=820e6", "--reduction");
  CHECK(l.form == ReductionForm::layer);
  CHECK_FALSE(l.resolved);
  CHECK(l.layer.h == 125e-6);
  CHECK(l.layer.G3 == 820e6);
  CHECK(l.layer.tau_limit == 0.0);
  CHECK(reduction_label(l) == "layer h=125 um, G3=820 MPa");
  const ReductionSpec t = parse_reduction_spec("layer: h = 1e-4, G3 = 5e8, tau_c = 3e8", "x");
  CHECK(t.layer.tau_limit == 3e8);
  CHECK(reduction_label(t) == "layer h=100 um, G3=500 MPa, tau_c=300 MPa");
  // Factors only: a layer has none before a patch is known.
  CHECK_THROWS_WITH(parse_reduction("layer:h=125e-6,G3=820e6", "--reduction"),
                    Catch::Contains("--reduction") && Catch::Contains("needs the contact patch"));
  auto bad = [](const char* text, const char* what) {
    CHECK_THROWS_WITH(parse_reduction_spec(text, "--reduction"), Catch::Contains("--reduction") && Catch::Contains(what));
  };
  bad("layer:h=125e-6", "needs both h and G3");
  bad("layer:G3=820e6", "needs both h and G3");
  bad("layer:h=0,G3=820e6", "(0, 0.1] m");
  bad("layer:h=0.5,G3=820e6", "(0, 0.1] m");
  bad("layer:h=1e-4,G3=-1", "(0, 1e12] Pa");
  bad("layer:h=1e-4,G3=8e8,tau_c=0", "(0, 1e11] Pa");
  bad("layer:h=1e-4,G3=8e8,depth=3", "unknown layer parameter 'depth'");
  bad("layer:h=1e-4,G3", "has no value");
  bad("layer:h=abc,G3=8e8", "cannot read 'abc'");
  bad("layer:h=1e-5,G3=1e9,h=2e-5", "layer parameter 'h' given twice");
  bad("layer:h=1e-5,G3=1e9,G3=2e9", "layer parameter 'G3' given twice");
  bad("layer:h=1e-5,G3=1e9,tau_c=3e8,tau_c=1e8", "layer parameter 'tau_c' given twice");
}

TEST_CASE("reduction lists: commas, brackets, layers and semicolons", "[reduction]") {
  const auto l = parse_reduction_list("1,0.9,0.5,elastic_fe,(0.72,0.5,0.5),layer:h=125e-6,G3=820e6,elastoplastic_fe",
                                      "--reductions");
  REQUIRE(l.size() == 7);
  CHECK(l[0].form == ReductionForm::uniform);
  CHECK(l[1].k.k11 == 0.9);
  CHECK(l[3].form == ReductionForm::preset);
  CHECK(l[4].form == ReductionForm::factors);
  CHECK(l[4].k.k11 == 0.72);
  CHECK(l[5].form == ReductionForm::layer);
  CHECK(l[5].layer.G3 == 820e6);
  CHECK(l[6].preset == "elastoplastic_fe");
  const auto s = parse_reduction_list("0.72,0.56,0.56; 0.5 ;layer:h=1e-4,G3=8e8,tau_c=2e8", "--reductions");
  REQUIRE(s.size() == 3);
  CHECK(s[0].form == ReductionForm::factors);
  CHECK(s[1].k.k22 == 0.5);
  CHECK(s[2].layer.tau_limit == 2e8);
  CHECK_THROWS_WITH(parse_reduction_list("1,,0.5", "--reductions"), Catch::Contains("entry 2") && Catch::Contains("empty"));
  CHECK_THROWS_WITH(parse_reduction_list("1,2", "--reductions"),
                    Catch::Contains("--reductions entry 2") && Catch::Contains("(0, 1.5]"));
  CHECK_THROWS_WITH(parse_reduction_list("1,soapy", "--reductions"), Catch::Contains("unknown reduction 'soapy'"));
  // An entry twice (it ran twice into one folder): the same text, or the same factors written otherwise.
  CHECK_THROWS_WITH(parse_reduction_list("1,1", "--reductions"),
                    Catch::Contains("--reductions: entry 2 ('1') repeats entry 1 ('1')"));
  CHECK_THROWS_WITH(parse_reduction_list("0.5,elastic_fe,0.50", "--reductions"),
                    Catch::Contains("entry 3 ('0.50') repeats entry 1 ('0.5')"));
  CHECK(parse_reduction_list("0.5,(0.5,0.5,0.5)", "--reductions").size() == 2);  // one number and a triple
  CHECK_THROWS_AS(parse_reduction_list("", "--reductions"), railsim::InputError);
}

TEST_CASE("reduction factors out of range name the factor and the range", "[reduction]") {
  CHECK_THROWS_WITH(parse_reduction("1.7", "--reduction"), Catch::Contains("k11") && Catch::Contains("(0, 1.5]"));
  CHECK_THROWS_WITH(parse_reduction("0.5,0,0.5", "--reduction"), Catch::Contains("k22"));
  CHECK_THROWS_WITH(parse_reduction("0.5,0.5", "--reduction"), Catch::Contains("expected three"));
  CHECK(parse_reduction("none", "x").k11 == 1.0);
}
