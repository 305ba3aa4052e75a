// The one reader of a typed answer (course/answer_number.hpp) and the feedback built on it: a number as people
// write it, its unit checked, anything else refused in one line; the slips `diff` names, told in the lesson too;
// a right answer without a share of rounding noise.

#include "course/answer_number.hpp"
#include "course/lesson.hpp"
#include "course/slips.hpp"
#include "formats/input_error.hpp"

#include <doctest/doctest.h>

#include <string>

namespace impulse::test {

namespace {

std::string refusal(std::string_view typed, std::string_view unit) {
    try {
        course::read_answer_number(typed, unit);
    } catch (const formats::InputError& e) {
        CHECK(e.where() == "answer");
        CHECK(e.problem().find('\n') == std::string::npos);
        return e.problem();
    }
    FAIL("\"" << std::string(typed) << "\" was read as a number");
    return {};
}

}  // namespace

TEST_CASE("an answer is read with a decimal point or comma, a typographic minus, an exponent or as a fraction") {
    CHECK(course::read_answer_number("3.2", "m/s") == 3.2);
    CHECK(course::read_answer_number(" 15,0 ", "N·s") == 15.0);  // read as 150 by the window before
    CHECK(course::read_answer_number("−3", "m/s") == -3.0);
    CHECK(course::read_answer_number("+0.5", "") == 0.5);
    CHECK(course::read_answer_number("-1.5e-2", "m") == -0.015);
    CHECK(course::read_answer_number("7,04E-3", "m") == doctest::Approx(0.00704));
    CHECK(course::read_answer_number("1/60", "s") == doctest::Approx(1.0 / 60.0));
    CHECK(course::read_answer_number("-3 / 4", "") == -0.75);
    CHECK(course::read_answer_number(".5", "") == 0.5);
}

TEST_CASE("a unit typed after the answer must be the question's, however its product and power are written") {
    CHECK(course::read_answer_number("7.5 m/s", "m/s") == 7.5);
    CHECK(course::read_answer_number("7.5m/s", "m/s") == 7.5);
    CHECK(course::read_answer_number("15 N*s", "N·s") == 15.0);
    CHECK(course::read_answer_number("15 N s", "N·s") == 15.0);
    CHECK(course::read_answer_number("15 N.s", "N·s") == 15.0);
    CHECK(course::read_answer_number("9.81 m/s^2", "m/s²") == 9.81);
    CHECK(course::read_answer_number("9.81 m/s2", "m/s²") == 9.81);
    CHECK(course::read_answer_number("1/60 s", "s") == doctest::Approx(1.0 / 60.0));
    CHECK(course::read_answer_number("0.5 1/kg", "1/kg") == 0.5);
    CHECK(refusal("7.5 km/h", "m/s") ==
          "the answer is in m/s, not \"km/h\": type it in m/s (the unit may follow the number, or be left out)");
    CHECK(refusal("3 m/s", "m/s²").starts_with("the answer is in m/s², not \"m/s\""));
    CHECK(refusal("0.3 m", "") == "this value has no unit: type the number alone, without \"m\"");
}

TEST_CASE("anything that is not one number is refused with what to type, never read as another number") {
    CHECK(refusal("", "m/s") == "type a number, e.g. 3.2, -1.5e-2, 3,2 or 1/60");
    CHECK(refusal("seven", "m/s") == "\"seven\" is not a number: type a number, e.g. 3.2, -1.5e-2, 3,2 or 1/60");
    CHECK(refusal("1,000.5", "m").starts_with("\"1,000.5\" has more than one decimal mark"));
    CHECK(refusal("1.2.3", "m").starts_with("\"1.2.3\" has more than one decimal mark"));
    CHECK(refusal("1/0", "").starts_with("\"1/0\" divides by 0"));
    CHECK(refusal("3 4", "m").starts_with("the answer is in m, not \"4\""));
    CHECK(refusal("1e999", "").starts_with("\"1e999\""));
}

TEST_CASE("a wrong number that is the right one with another sign, in degrees or a power of ten off is named") {
    CHECK(course::likely_slip(3.0, -3.0) ==
          "the opposite sign: check the order of a cross product, or which body "
          "is body 0");
    CHECK(course::likely_slip(0.00704, 7.04).starts_with("1000 times the value: a unit slip"));
    CHECK(course::likely_slip(0.2, 0.2 * 180 / 3.14159265358979).starts_with("57.3 times the value"));
    CHECK(course::likely_slip(5.0, 0.05).starts_with("the value divided by 100"));
    CHECK(course::likely_slip(3.0, 3.5).empty());
    CHECK(course::likely_slip(0.0, 3.0).empty());
    // Within the question's own tolerance: −2.95 for 3 with 2 % allowed is a sign slip too.
    CHECK(course::likely_slip(3.0, -2.95, 0.02).starts_with("the opposite sign"));
    CHECK(course::likely_slip(3.0, -2.95).empty());
}

TEST_CASE("the lesson's feedback names the slip, and a right answer says right without a share of noise") {
    course::Question q{course::Question::Kind::predict, "?", "x", {0.02, std::nullopt}, {}, {}};
    course::Answer a{nlohmann::ordered_json(3.0), "contact_velocity", "m/s", -1, "3 m/s"};
    CHECK(course::check_answer(q, a, "-3").feedback ==
          "not quite: the opposite sign: check the order of a cross product, or which body is body 0; try again, or "
          "skip to see the engine's value");
    CHECK(course::check_answer(q, a, "4").feedback ==
          "not quite: 33.3 % too high; try again, or skip to see the engine's value");
    CHECK(course::check_answer(q, a, "3,0 m/s").feedback == "right: the engine has 3 m/s");
    CHECK(course::check_answer(q, a, "3.03").feedback == "right: the engine has 3 m/s (you were 1 % off)");
    // −0.2 typed for −0.2 + 2.8e-17: right, with no "1.39e-14 % off".
    course::Answer noisy{nlohmann::ordered_json(-0.2 + 2.8e-17), "angular_change", "rad", -1, "-0.2 rad"};
    CHECK(course::check_answer(q, noisy, "-0.2").feedback == "right: the engine has -0.2 rad");
    // 7.04 for 0.00704 m: a unit slip, not "99928 % too high".
    course::Answer small{nlohmann::ordered_json(0.00704), "amount", "m", -1, "0.00704 m"};
    CHECK(course::check_answer(q, small, "7.04").feedback.starts_with("not quite: 1000 times the value: a unit slip"));
    CHECK_THROWS_AS(course::check_answer(q, a, "3 m"), formats::InputError);
}

}  // namespace impulse::test
