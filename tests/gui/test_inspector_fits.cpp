// The inspector at 1280x800 cuts none of its navigator's rows, its settings' names and values, or its contacts
// list's cells: every one of them that shows on the screen at all shows whole, read back from what ImGui drew
// (gui/visible_text.hpp), whose glyphs outside a panel's clip rectangle are not there.

#include "course/item_labels.hpp"
#include "gui/layout_check.hpp"
#include "gui/visible_text.hpp"
#include "model/replay.hpp"
#include "formats/settings_names.hpp"
#include "support/opened.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <imgui.h>

namespace impulse::test {

namespace {

// No text of `expected` shows cut in the panel `what` (the window of that name and its children).
// `shown`: each must also show (whole).
void check_whole(const std::vector<gui::VisibleRun>& all_runs, const std::vector<std::string>& expected,
                 const std::string& what, bool shown = false) {
    std::vector<gui::VisibleRun> runs;
    for (const gui::VisibleRun& r : all_runs)
        if (r.window == what || r.window.starts_with(what + "/")) runs.push_back(r);
    for (const std::string& e : expected) {
        // Cut: a run that is the text's beginning and no more (what the panel's edge left of it).
        const auto cut = std::find_if(runs.begin(), runs.end(), [&](const gui::VisibleRun& r) {
            return r.text.size() >= 4 && r.text.size() < e.size() && e.starts_with(r.text);
        });
        const bool whole = std::any_of(runs.begin(), runs.end(),
                                       [&](const gui::VisibleRun& r) { return r.text.find(e) != std::string::npos; });
        if (cut != runs.end()) CHECK_MESSAGE(whole, what << ": \"" << e << "\" is cut to \"" << cut->text << "\"");
        if (shown) CHECK_MESSAGE(whole, what << ": \"" << e << "\" is not shown");
    }
}

}  // namespace

TEST_CASE("the inspector at 1280x800 cuts no navigator row, setting or contacts cell") {
    model::OpenOptions soft;
    soft.settings = {"preset=soft_step"};
    soft.frames = 2;
    struct Place {
        model::Session session;
        std::string go_to;
    };
    std::vector<Place> places;
    places.push_back({opened_session("cases/sliding_box"), "phase=velocity,iteration=2,step=impulse"});
    places.push_back({opened_session("stack_3", soft), "frame=1,phase=velocity,iteration=3"});
    places.push_back({opened_session("cases/ruler"), "phase=position,step=move_split"});
    int checked = 0;
    for (Place& p : places) {
        model::Session& session = p.session;
        session.move_to(model::resolve_goto(session.trace(), model::parse_goto(p.go_to, "g"), "g"));
        gui::OffscreenLayout layout(1280, 800);
        const gui::TextReader reader(*ImGui::GetIO().Fonts);
        gui::UiState state;
        layout.frame(session, state);
        layout.frame(session, state);
        const std::vector<gui::VisibleRun> runs = reader.read(*ImGui::GetDrawData());
        INFO(session.path() << " at " << p.go_to);
        // The navigator's rows of the cursor's stage (whole, or in two lines broken before the arrow).
        const Trace& trace = session.trace();
        const model::Cursor at = *session.cursor();
        std::vector<std::string> rows;
        for (int i = 0; i < model::item_count(trace.frames[static_cast<std::size_t>(at.frame)], at.stage); ++i) {
            const std::string label = course::item_label(trace, state.mask, at.frame, at.stage, i);
            const std::size_t arrow = label.find(" → ");
            rows.push_back(label.substr(0, arrow));
            if (arrow != std::string::npos) rows.push_back(label.substr(arrow + 1));
        }
        check_whole(runs, rows, "Navigator");
        // The settings' names and the values their lists show.
        const ResolverSettings& s = session.settings();
        // The first settings show whole; those further down (the panel scrolls) are never cut where they show.
        check_whole(runs,
                    {"preset", "phase order", "velocity method", "position method", s.preset,
                     std::string(formats::name_of(formats::phase_order_names, s.phase_order)),
                     std::string(formats::name_of(formats::velocity_method_names, s.velocity_method)),
                     std::string(formats::name_of(formats::position_method_names, s.position_method))},
                    "Settings", true);
        check_whole(runs,
                    {"restitution cut-off", "orientation update", "velocity from acceleration",
                     std::string(formats::name_of(formats::orientation_update_names, s.orientation_update))},
                    "Settings");
        // The contacts list: its headers and each row's status.
        std::vector<std::string> cells{"pen. mm", "Δv m/s", "|g| N·s", "status"};
        for (const model::ContactRow& r : model::contact_rows(trace, at))
            cells.emplace_back(model::status_name(r.status));
        check_whole(runs, cells, "Contacts", true);
        ++checked;
    }
    CHECK(checked == 3);
}

}  // namespace impulse::test
