#include "gui/layout_memory.hpp"

#include "course/progress.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_files.hpp"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace impulse::gui {

namespace {

using json = nlohmann::json;

// Pixels across (or down) a window of `extent`, as a share of it; 0 (the default) stays 0.
double share(float pixels, float extent) {
    return pixels > 0 && extent > 0 ? pixels / extent : 0.0;
}

}  // namespace

std::optional<std::filesystem::path> layout_file() {
    const std::optional<std::filesystem::path> progress = course::progress_file();
    if (!progress) return std::nullopt;
    return progress->parent_path() / "layout.json";
}

std::string layout_text(const PanelSizes& s, float width, float height) {
    (void)height;  // the shares that are heights are shares already
    const json j{{"format", "impulse-lab-layout"},
                 {"version", 1},
                 {"lesson_width", share(s.lesson_width, width)},
                 {"left_width", share(s.left_width, width)},
                 {"right_width", share(s.right_width, width)},
                 {"derivation_share", s.derivation_share},
                 {"scene_share", s.scene_share}};
    return j.dump(2) + "\n";
}

PanelSizes layout_from_text(std::string_view text, float width, float height) {
    (void)height;
    PanelSizes s;
    const json j = json::parse(text, nullptr, false);
    if (!j.is_object() || j.value("format", "") != "impulse-lab-layout") return s;
    // A share from 5 % to 95 % of the window; anything else is not a layout this program wrote.
    const auto read = [&j](const char* key) {
        const auto found = j.find(key);
        if (found == j.end() || !found->is_number()) return 0.0f;
        const double v = found->get<double>();
        return v >= 0.05 && v <= 0.95 ? static_cast<float>(v) : 0.0f;
    };
    s.lesson_width = read("lesson_width") * width;
    s.left_width = read("left_width") * width;
    s.right_width = read("right_width") * width;
    s.derivation_share = read("derivation_share");
    s.scene_share = read("scene_share");
    return s;
}

PanelSizes load_layout(float width, float height) {
    const std::optional<std::filesystem::path> file = layout_file();
    if (!file) return {};
    std::error_code missing;
    if (!std::filesystem::is_regular_file(*file, missing)) return {};  // none yet: the defaults
    try {
        return layout_from_text(formats::read_input_file(file->string()), width, height);
    } catch (...) {
        return {};  // unreadable: the defaults, as for none
    }
}

bool save_layout(const PanelSizes& sizes, float width, float height) {
    const std::optional<std::filesystem::path> file = layout_file();
    if (!file) return false;
    try {
        std::filesystem::create_directories(file->parent_path());
        formats::write_file_atomically(file->string(), layout_text(sizes, width, height), "layout");
        return true;
    } catch (...) {
        return false;  // a layout not kept is no error: the next window starts from the defaults
    }
}

void RememberedLayout::take_up(UiState& state) {
    if (!window_ || taken_) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    state.sizes = loaded_ = load_layout(size.x, size.y);
    taken_ = true;
}

void RememberedLayout::keep(const UiState& state) const {
    const PanelSizes& s = state.sizes;
    const bool changed = s.lesson_width != loaded_.lesson_width || s.left_width != loaded_.left_width ||
                         s.right_width != loaded_.right_width || s.derivation_share != loaded_.derivation_share ||
                         s.scene_share != loaded_.scene_share;
    if (!window_ || !taken_ || !changed) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    save_layout(s, size.x, size.y);
}

}  // namespace impulse::gui
