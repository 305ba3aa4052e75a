// Every blank cell of every shipped lesson's and case's worksheet can be worked out from what the sheet gives.
//
// A hand worker (hand_worker.hpp) fills the sheet as a student would, from its inputs and the cells already filled.
// Its filled sheet is then graded by diff against the reference at diff's default tolerance: every cell must match,
// none may stay blank. A cell whose inputs the sheet forgot leaves its step undone and the test names what was
// missing.

#include "hand_worker.hpp"

#include "course/diff.hpp"
#include "course/lesson.hpp"
#include "course/worksheet.hpp"
#include "formats/trace_json.hpp"
#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

using namespace impulse;
using namespace impulse::course;

namespace {

// Works the sheet out by hand and grades the answers as diff grades a student's.
void check_by_hand(const std::string& what, const formats::json& reference, const Worksheet& sheet) {
    CAPTURE(what);
    const formats::json document = worksheet_json(sheet);
    const test::HandWork work = test::work_by_hand(document, reference);
    for (const std::string& step : work.undone) CHECK_MESSAGE(false, step);
    const DiffReport report = diff_worksheet(reference, read_worksheet_json(work.filled), Tolerance{});
    for (const Finding& f : report.findings)
        CHECK_MESSAGE(false, finding_kind_name(f.kind) << " " << f.path << ": expected " << f.expected.dump()
                                                       << ", worked out " << f.found.dump());
    CHECK(report.matched > 0);
    CHECK(report.all_match());
}

}  // namespace

TEST_CASE("every blank of every shipped lesson's worksheet can be worked out by hand from the inputs it gives") {
    for (const std::filesystem::path& file : course::lesson_files(IMPULSE_SOURCE_DIR "/lessons")) {
        const course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(file));
        const formats::json reference = formats::trace_json(lesson.session.trace());
        const std::vector<model::Cursor> places = places_with_cells(lesson.session, lesson.places, &reference);
        REQUIRE_FALSE(places.empty());
        check_by_hand(file.filename().string(), reference, make_worksheet(lesson.session, places, &reference));
    }
}

TEST_CASE("every blank of every shipped case's default worksheet can be worked out by hand from the inputs it gives") {
    for (const auto& entry : std::filesystem::directory_iterator(IMPULSE_SOURCE_DIR "/scenes/cases")) {
        const std::string name = "cases/" + entry.path().stem().string();
        const model::Session session = test::opened_session(name);
        check_by_hand(name, formats::trace_json(session.trace()),
                      make_worksheet(session, default_places(session.trace())));
    }
}

TEST_CASE("an input is rounded to the shortest decimal within a thousandth of diff's default tolerance") {
    // diff matches |found − expected| ≤ 1e-12 + 1e-9·|expected|; an input may move 1e-15 + 1e-12·|x|.
    CHECK(rounded_for_hand_work(24.000000000000004) == 24.0);  // 4e-15 away: within 2.4e-11
    CHECK(rounded_for_hand_work(0.3999999999999999) == 0.4);
    CHECK(rounded_for_hand_work(-0.14941811900000002) == -0.149418119);
    CHECK(rounded_for_hand_work(1.1102230246251565e-16) == 0.0);  // below 1e-15: rounding noise around 0
    CHECK(std::signbit(rounded_for_hand_work(-0.0)) == false);    // and −0 is written 0
    // 12 digits would be 4.2e-13 off, over the 1.4e-13 allowed; 13 digits are 1.7e-14 off.
    CHECK(rounded_for_hand_work(0.1407367320754168) == 0.1407367320754);
    CHECK(rounded_for_hand_work(2.5e-14) == 2.5e-14);  // a small value that is not noise keeps its digits
    CHECK(rounded_for_hand_work(formats::json::array({1.0000000000000002, "x", true})) ==
          formats::json::array({1.0, "x", true}));
}
