#pragma once
// The panel layout a window remembers: where the user dragged the borders, kept as shares of the window (so a
// window of another size opens with the same proportions) in layout.json beside the progress file. Headless runs
// neither read nor write it: their pictures must not depend on a user's layout.

#include "gui/ui_state.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace impulse::gui {

// Where the layout is kept ($XDG_CONFIG_HOME/impulse-lab/layout.json); none without a config folder.
std::optional<std::filesystem::path> layout_file();

// The sizes as the file's text, given the window's size in pixels.
std::string layout_text(const PanelSizes& sizes, float width, float height);
// The sizes from the file's text for a window of this size; anything unreadable or out of range is left at its
// default (0), never an error: a layout is a convenience.
PanelSizes layout_from_text(std::string_view text, float width, float height);

// Reads the remembered layout, or the defaults when there is none.
PanelSizes load_layout(float width, float height);
// Keeps the layout; a failure to write is ignored (returns false).
bool save_layout(const PanelSizes& sizes, float width, float height);

// A window's run: the remembered layout taken up once the window's size is known (its first frame), and kept when
// the window closes if the user changed it.
class RememberedLayout {
public:
    explicit RememberedLayout(bool window) : window_(window) {}
    // Call each frame after the frame began (the display size is then known).
    void take_up(UiState& state);
    void keep(const UiState& state) const;

private:
    bool window_;
    bool taken_ = false;
    PanelSizes loaded_;
};

}  // namespace impulse::gui
