#include "bench/bench_charts.hpp"

#include "bench/chart_canvas.hpp"
#include "settings/settings.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>

namespace impulse::bench {

namespace {

using bench::BenchRun;
using bench::BenchScene;
using bench::RunResult;

constexpr ImU32 white = IM_COL32(255, 255, 255, 255);
constexpr ImU32 ink = IM_COL32(30, 30, 30, 255);
constexpr ImU32 faint = IM_COL32(120, 120, 120, 255);
constexpr ImU32 grid_major = IM_COL32(205, 205, 205, 255);
constexpr ImU32 grid_minor = IM_COL32(236, 236, 236, 255);
constexpr float text_size = 15.0f;

// Colour-blind-safe hues (Okabe and Ito), one per method of ours in the order given; the other engines have
// their own colours and shapes (below), whatever else is charted.
ImU32 our_colour(std::size_t i) {
    constexpr ImU32 colours[] = {IM_COL32(0, 114, 178, 255),   IM_COL32(230, 159, 0, 255), IM_COL32(0, 158, 115, 255),
                                 IM_COL32(204, 121, 167, 255), IM_COL32(213, 94, 0, 255),  IM_COL32(86, 180, 233, 255),
                                 IM_COL32(120, 120, 0, 255)};
    return colours[i % std::size(colours)];
}

// How a method is drawn: its colour and marker shape (0-4 ours by position, 5-7 the other engines).
struct MethodStyle {
    ImU32 colour;
    int shape;
};

MethodStyle method_style(const std::vector<std::string>& methods, std::size_t m) {
    constexpr std::array<std::pair<std::string_view, MethodStyle>, 3> engines{{
        {"bullet", {IM_COL32(20, 20, 20, 255), 5}},
        {"ode", {IM_COL32(140, 80, 20, 255), 6}},
        {"mujoco", {IM_COL32(130, 30, 130, 255), 7}},
    }};
    for (const auto& [name, style] : engines)
        if (methods[m] == name) return style;
    std::size_t ours = 0;  // the position among our methods only
    for (std::size_t i = 0; i < m; ++i)
        if (std::none_of(engines.begin(), engines.end(), [&](const auto& e) { return methods[i] == e.first; })) ++ours;
    return {our_colour(ours), static_cast<int>(ours % 5)};
}

void text(ImDrawList& list, ImVec2 at, ImU32 colour, const std::string& s, float size = text_size) {
    list.AddText(ImGui::GetFont(), size, at, colour, s.c_str());
}

float text_width(const std::string& s, float size = text_size) {
    return ImGui::GetFont()->CalcTextSizeA(size, 1e9f, 0.0f, s.c_str()).x;
}

// `s` cut to fit `width` pixels, ending in "…" when it had to be cut (a cell's text must not run into the next).
std::string fitted(const std::string& s, float width, float size = text_size) {
    if (text_width(s, size) <= width) return s;
    std::string cut = s;
    while (!cut.empty() && text_width(cut + "…", size) > width) {
        cut.pop_back();
        while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();  // UTF-8
    }
    return cut + "…";
}

// The isolated bounce's one known artefact, said where it shows: a method with Baumgarte's bias (the pgs preset)
// leaves faster than c v, by the push beta (p - slop) / h it adds to the separating velocity (docs/methods.md).
std::string baumgarte_note(const BenchRun& run, const BenchScene& spec) {
    if (spec.metric != bench::Metric::restitution_error) return {};
    std::string methods;
    for (const std::string& m : run.methods)
        if (const std::optional<ResolverSettings> s = preset(m); s && s->baumgarte)
            methods += (methods.empty() ? "" : ", ") + m;
    return methods.empty() ? std::string() : methods + ": Baumgarte adds β(p − slop)/h to the bounce";
}

// Marker shapes by method, so series stay apart in grey too: filled when the run held, hollow when it failed.
void marker(ImDrawList& list, int shape, ImVec2 c, ImU32 colour, bool filled, float r = 5.5f) {
    if (!filled) list.AddCircleFilled(c, r + 1.0f, white, 16);  // hollow: white inside, over the lines
    switch (shape) {
        case 0:
            filled ? list.AddCircleFilled(c, r, colour, 16) : list.AddCircle(c, r, colour, 16, 2.0f);
            break;
        case 1:
            filled ? list.AddRectFilled({c.x - r, c.y - r}, {c.x + r, c.y + r}, colour)
                   : list.AddRect({c.x - r, c.y - r}, {c.x + r, c.y + r}, colour, 0, 0, 2.0f);
            break;
        case 2: {
            const ImVec2 a{c.x, c.y - r * 1.2f}, b{c.x - r * 1.1f, c.y + r * 0.8f}, d{c.x + r * 1.1f, c.y + r * 0.8f};
            filled ? list.AddTriangleFilled(a, b, d, colour) : list.AddTriangle(a, b, d, colour, 2.0f);
            break;
        }
        case 3: {
            const float q = r * 1.3f;
            const ImVec2 a{c.x, c.y - q}, b{c.x + q, c.y}, d{c.x, c.y + q}, e{c.x - q, c.y};
            filled ? list.AddQuadFilled(a, b, d, e, colour) : list.AddQuad(a, b, d, e, colour, 2.0f);
            break;
        }
        case 5: {  // bullet: a triangle pointing down
            const ImVec2 a{c.x, c.y + r * 1.2f}, b{c.x + r * 1.1f, c.y - r * 0.8f}, d{c.x - r * 1.1f, c.y - r * 0.8f};
            filled ? list.AddTriangleFilled(a, b, d, colour) : list.AddTriangle(a, b, d, colour, 2.0f);
            break;
        }
        case 6:  // ode: a plus
            list.AddLine({c.x - r * 1.2f, c.y}, {c.x + r * 1.2f, c.y}, colour, filled ? 3.0f : 1.5f);
            list.AddLine({c.x, c.y - r * 1.2f}, {c.x, c.y + r * 1.2f}, colour, filled ? 3.0f : 1.5f);
            break;
        case 7: {  // mujoco: a hexagon
            ImVec2 corners[6];
            for (int k = 0; k < 6; ++k)
                corners[k] = {c.x + r * 1.15f * std::cos(k * 1.0471976f), c.y + r * 1.15f * std::sin(k * 1.0471976f)};
            filled ? list.AddConvexPolyFilled(corners, 6, colour) : list.AddPolyline(corners, 6, colour, true, 2.0f);
            break;
        }
        default:
            list.AddLine({c.x - r, c.y - r}, {c.x + r, c.y + r}, colour, filled ? 3.0f : 1.5f);
            list.AddLine({c.x - r, c.y + r}, {c.x + r, c.y - r}, colour, filled ? 3.0f : 1.5f);
            break;
    }
}

// 10^k as an axis label: plain from 0.001 to 1000, else 1e-5.
std::string decade_label(int k) {
    char s[32];
    if (k >= -3 && k <= 3)
        std::snprintf(s, sizeof s, "%g", std::pow(10.0, k));
    else
        std::snprintf(s, sizeof s, "1e%d", k);
    return s;
}

struct LogAxis {
    int lo = 0, hi = 1;  // decades
    static LogAxis around(std::vector<double> values) {
        values.erase(
            std::remove_if(values.begin(), values.end(), [](double v) { return !(v > 0.0) || !std::isfinite(v); }),
            values.end());
        LogAxis a;
        if (values.empty()) return a;
        const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
        // A twentieth of a decade of room, so a point never sits on the frame.
        a.lo = static_cast<int>(std::floor(std::log10(*mn) - 0.05));
        a.hi = static_cast<int>(std::ceil(std::log10(*mx) + 0.05));
        if (a.hi <= a.lo) a.hi = a.lo + 1;
        if (a.hi - a.lo > 12) a.lo = a.hi - 12;  // tiny errors (1e-16) are drawn on the bottom edge
        return a;
    }
    // 0..1 along the axis, clamped (zero and tiny values sit on the lower edge).
    float at(double v) const {
        if (!(v > 0.0)) return 0.0f;
        const double t = (std::log10(v) - lo) / (hi - lo);
        return static_cast<float>(std::clamp(t, 0.0, 1.0));
    }
};

void dashed_line(ImDrawList& list, ImVec2 a, ImVec2 b, ImU32 colour, float dash = 6.0f) {
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    for (float s = 0.0f; s < length; s += 2.0f * dash) {
        const float e = std::min(length, s + dash);
        list.AddLine({a.x + (b.x - a.x) * s / length, a.y + (b.y - a.y) * s / length},
                     {a.x + (b.x - a.x) * e / length, a.y + (b.y - a.y) * e / length}, colour, 1.5f);
    }
}

// The first of `options` where a box of w x h covers none of `taken`.
std::optional<ImVec2> free_place(const std::vector<ChartBox>& taken, std::span<const ImVec2> options, float w,
                                 float h) {
    for (const ImVec2& o : options) {
        const ChartBox box{o.x, o.y, o.x + w, o.y + h};
        if (std::none_of(taken.begin(), taken.end(), [&](const ChartBox& t) { return t.overlaps(box); })) return o;
    }
    return std::nullopt;
}

void panel(ImDrawList& list, ImVec2 origin, ImVec2 size, const BenchRun& run, const BenchScene& spec) {
    std::vector<const RunResult*> rows;
    for (const RunResult& r : run.rows)
        if (r.scene == spec.name) rows.push_back(&r);
    // The error axis shows a decade above the target and two below it, whatever the runs gave.
    std::vector<double> times, errors;
    if (spec.verdict) errors = {spec.target * 10.0, spec.target / 100.0};
    int nan_runs = 0;
    for (const RunResult* r : rows) {
        if (std::isnan(r->accuracy.error)) {
            ++nan_runs;
            continue;
        }
        times.push_back(r->time_per_step * 1e3);
        errors.push_back(r->accuracy.error);
    }
    const LogAxis x = LogAxis::around(times), y = LogAxis::around(errors);

    const std::string unit(bench::metric_unit(spec.metric));
    const std::string title = spec.name + " — " + std::string(bench::metric_meaning(spec.metric));
    text(list, {origin.x + 8, origin.y + 4}, ink, title, 17.0f);
    // Boxes no N label may cover: the words above the plot, the axes' labels, markers, labels.
    std::vector<ChartBox> taken{{origin.x + 8, origin.y + 4, origin.x + 8 + text_width(title, 17.0f), origin.y + 22}};
    const ImVec2 p0{origin.x + 66, origin.y + 46};  // plot's top left
    // Bottom right; the time labels sit 12 px below the plot, clear of the markers an error of 0 puts on its edge.
    const ImVec2 p1{origin.x + size.x - 16, origin.y + size.y - 54};
    const std::string axis = "error" + (unit.empty() ? std::string(" (ratio)") : " (" + unit + ")") +
                             (nan_runs ? "   " + std::to_string(nan_runs) + " NaN run(s) not drawn" : "");
    text(list, {origin.x + 8, origin.y + 25}, faint, axis);
    taken.push_back({origin.x + 8, origin.y + 25, origin.x + 8 + text_width(axis), origin.y + 25 + text_size});
    if (const std::string note = baumgarte_note(run, spec); !note.empty()) {
        const float from = origin.x + 8 + text_width(axis) + 16, room = origin.x + size.x - 12 - from;
        const std::string shown = fitted(note, room, 13.5f);
        text(list, {from, origin.y + 26}, IM_COL32(0, 120, 90, 255), shown, 13.5f);
        taken.push_back({from, origin.y + 26, from + text_width(shown, 13.5f), origin.y + 26 + 13.5f});
    }
    const auto px = [&](double t) { return p0.x + x.at(t) * (p1.x - p0.x); };
    const auto py = [&](double e) { return p1.y - y.at(e) * (p1.y - p0.y); };

    // Grid: minor lines at 2..9 of each decade, major at the decades, with labels.
    for (int k = x.lo; k < x.hi; ++k)
        for (int m = 2; m <= 9; ++m)
            list.AddLine({px(m * std::pow(10.0, k)), p0.y}, {px(m * std::pow(10.0, k)), p1.y}, grid_minor);
    for (int k = y.lo; k < y.hi; ++k)
        for (int m = 2; m <= 9; ++m)
            list.AddLine({p0.x, py(m * std::pow(10.0, k))}, {p1.x, py(m * std::pow(10.0, k))}, grid_minor);
    for (int k = x.lo; k <= x.hi; ++k) {
        const float X = px(std::pow(10.0, k));
        list.AddLine({X, p0.y}, {X, p1.y}, grid_major);
        const std::string label = decade_label(k);
        text(list, {X - text_width(label) / 2, p1.y + 12}, ink, label);
        taken.push_back({X - text_width(label) / 2, p1.y + 12, X + text_width(label) / 2, p1.y + 12 + text_size});
    }
    for (int k = y.lo; k <= y.hi; ++k) {
        const float Y = py(std::pow(10.0, k));
        list.AddLine({p0.x, Y}, {p1.x, Y}, grid_major);
        const std::string label = decade_label(k);
        text(list, {p0.x - 6 - text_width(label), Y - 8}, ink, label);
        taken.push_back({p0.x - 6 - text_width(label), Y - 8, p0.x - 6, Y - 8 + text_size});
    }
    list.AddRect(p0, p1, faint);
    const std::string x_name = "time per step (ms)";
    text(list, {(p0.x + p1.x - text_width(x_name)) / 2, p1.y + 30}, ink, x_name);

    // The target: configurations below the dashed line meet it (its label goes where no marker is, below). A
    // scene that declares none has no line.
    if (spec.verdict) {
        const float target_y = py(spec.target);
        dashed_line(list, {p0.x, target_y}, {p1.x, target_y}, IM_COL32(90, 90, 90, 255));
    } else {
        const std::string none = "no bench target declared: no verdict";
        text(list, {p0.x + 4, p0.y + 4}, IM_COL32(90, 90, 90, 255), none);
        taken.push_back({p0.x + 4, p0.y + 4, p0.x + 4 + text_width(none), p0.y + 20});
    }

    // Every run's marker where its data puts it, then moved aside (with a thin line back to that place) when
    // another marker is already there: equal errors are common (two counts both at rest, 0 on the bottom edge).
    struct Placed {
        const RunResult* run;
        std::size_t method;
        ImVec2 at;      // where the data puts it
        ImVec2 marker;  // where it is drawn
    };
    std::vector<Placed> placed;
    std::vector<ChartPoint> places;
    for (std::size_t m = 0; m < run.methods.size(); ++m)
        for (const RunResult* r : rows) {
            if (r->method != run.methods[m] || std::isnan(r->accuracy.error)) continue;
            const ImVec2 at{px(r->time_per_step * 1e3), py(r->accuracy.error)};
            placed.push_back({r, m, at, at});
            places.push_back({at.x, at.y});
        }
    // A marker is about 12 px across; the bottom edge holds errors of 0, so markers may sit a little below it.
    const std::vector<ChartPoint> drawn = dodged_markers(places, 15.0f, {p0.x - 2, p0.y - 2}, {p1.x + 2, p1.y + 5});
    for (std::size_t i = 0; i < placed.size(); ++i) placed[i].marker = {drawn[i].x, drawn[i].y};

    // The Pareto front of the runs that held, under the markers: a thick grey line through them in time order.
    std::vector<bench::TimeError> points;
    for (const Placed& p : placed)
        points.push_back({p.run->time_per_step * 1e3, p.run->accuracy.error, p.run->accuracy.holds});
    const std::vector<std::size_t> front = bench::pareto_front(points);
    std::vector<ImVec2> front_points;
    for (const std::size_t i : front) front_points.push_back(placed[i].marker);
    if (front_points.size() > 1)
        list.AddPolyline(front_points.data(), static_cast<int>(front_points.size()), IM_COL32(150, 150, 150, 140), 0,
                         6.0f);
    for (const ImVec2& p : front_points) list.AddCircle(p, 10.0f, IM_COL32(110, 110, 110, 255), 20, 1.5f);

    // One series per method: a thin line in N order through its markers.
    for (std::size_t m = 0; m < run.methods.size(); ++m) {
        std::vector<ImVec2> line;
        for (const Placed& p : placed)
            if (p.method == m) line.push_back(p.marker);
        if (line.size() > 1)
            list.AddPolyline(line.data(), static_cast<int>(line.size()),
                             (method_style(run.methods, m).colour & 0x00FFFFFF) | 0x90000000, 0, 1.5f);
    }
    // Markers, each with a thin line from its data's place when it had to move, then N beside each in the first
    // place free of other labels and markers.
    for (const Placed& p : placed) {
        if (p.marker.x != p.at.x || p.marker.y != p.at.y) {
            list.AddLine(p.at, p.marker, (method_style(run.methods, p.method).colour & 0x00FFFFFF) | 0xB0000000, 1.0f);
            list.AddCircleFilled(p.at, 1.5f, method_style(run.methods, p.method).colour, 8);
        }
        const MethodStyle style = method_style(run.methods, p.method);
        marker(list, style.shape, p.marker, style.colour, p.run->accuracy.holds);
    }
    // Each marker's box, a front marker's ring (radius 10) included, so no label sits on either.
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const float half = std::find(front.begin(), front.end(), i) != front.end() ? 11.0f : 7.0f;
        const ImVec2 c = placed[i].marker;
        taken.push_back({c.x - half, c.y - half, c.x + half, c.y + half});
    }
    if (spec.verdict) {
        // The target's words on the dashed line where no marker is: above it at its left end, at its right end,
        // below it at either end, then anywhere along it.
        const std::string target = "target " + bench::metric_text(spec, spec.target);
        const float w = text_width(target), target_y = py(spec.target);
        std::vector<ImVec2> options{{p0.x + 4, target_y - 18},
                                    {p1.x - 4 - w, target_y - 18},
                                    {p0.x + 4, target_y + 3},
                                    {p1.x - 4 - w, target_y + 3}};
        for (float x = p0.x + 40; x + w < p1.x - 4; x += 40)
            for (const float y : {target_y - 18, target_y + 3}) options.push_back({x, y});
        const ImVec2 at = free_place(taken, options, w, text_size).value_or(options[0]);
        taken.push_back({at.x, at.y, at.x + w, at.y + text_size});
        text(list, at, IM_COL32(90, 90, 90, 255), target);
    }
    // N beside each marker, where no label covers another, a marker or the words round the plot, with a thin line
    // back when it had to go farther out; a marker with no free place keeps none, and the panel says how many.
    std::vector<ChartPoint> markers, sizes;
    for (const Placed& p : placed) {
        markers.push_back({p.marker.x, p.marker.y});
        sizes.push_back({text_width(std::to_string(p.run->n), 14.0f), 14.0f});
    }
    const std::vector<std::optional<ChartPoint>> labels =
        placed_labels(markers, sizes, taken, {p0.x, p0.y - 4, p1.x + 14, p1.y + 10});
    int crowded = 0;
    for (std::size_t i = 0; i < placed.size(); ++i) {
        if (!labels[i]) {
            ++crowded;
            continue;
        }
        const ImVec2 at{labels[i]->x, labels[i]->y};
        const ImU32 colour = method_style(run.methods, placed[i].method).colour;
        const ImVec2 centre{at.x + sizes[i].x / 2, at.y + sizes[i].y / 2}, c = placed[i].marker;
        if (std::hypot(centre.x - c.x, centre.y - c.y) > 20.0f)
            list.AddLine(c, centre, (colour & 0x00FFFFFF) | 0x70000000, 1.0f);
        text(list, at, colour, std::to_string(placed[i].run->n), 14.0f);
    }
    if (crowded > 0) {
        const std::string note = "N not shown: " + std::to_string(crowded) + " (no room)";
        text(list, {origin.x + 8, p1.y + 31}, faint, note, 13.0f);  // left of the centred axis title
    }
}

}  // namespace

std::vector<ChartPoint> dodged_markers(const std::vector<ChartPoint>& at, float apart, ChartPoint lo, ChartPoint hi) {
    std::vector<ChartPoint> drawn;
    const auto free_at = [&](ChartPoint c) {
        return std::none_of(drawn.begin(), drawn.end(),
                            [&](const ChartPoint& p) { return std::hypot(p.x - c.x, p.y - c.y) < apart; });
    };
    std::vector<ChartPoint> steps;
    for (int k = 1; k <= 4; ++k)
        for (const float side : {1.0f, -1.0f}) steps.push_back({side * static_cast<float>(k), 0});
    for (int k = 1; k <= 3; ++k)
        for (const ChartPoint d : {ChartPoint{1, -1}, ChartPoint{1, 1}, ChartPoint{-1, -1}, ChartPoint{-1, 1},
                                   ChartPoint{0, -1}, ChartPoint{0, 1}})
            steps.push_back({d.x * static_cast<float>(k), d.y * static_cast<float>(k)});
    for (const ChartPoint& own : at) {
        ChartPoint place = own;
        for (const ChartPoint& d : steps) {
            if (free_at(place)) break;
            const ChartPoint c{own.x + d.x * apart, own.y + d.y * apart};
            if (c.x >= lo.x && c.x <= hi.x && c.y >= lo.y && c.y <= hi.y && free_at(c)) place = c;
        }
        drawn.push_back(place);
    }
    return drawn;
}

std::vector<std::optional<ChartPoint>> placed_labels(const std::vector<ChartPoint>& markers,
                                                     const std::vector<ChartPoint>& sizes, std::vector<ChartBox> taken,
                                                     ChartBox bounds) {
    std::vector<std::optional<ChartPoint>> at;
    for (std::size_t i = 0; i < markers.size(); ++i) {
        const ChartPoint c = markers[i];
        const float w = sizes[i].x, h = sizes[i].y;
        std::optional<ChartPoint> found;
        // Rings round the marker: right, left, above, below, then the diagonals, each ring farther out.
        for (const float r : {9.0f, 14.0f, 22.0f, 32.0f, 46.0f}) {
            const ChartPoint options[] = {
                {c.x + r, c.y - h / 2}, {c.x - r - w, c.y - h / 2}, {c.x - w / 2, c.y - r - h}, {c.x - w / 2, c.y + r},
                {c.x + r, c.y - r - h}, {c.x + r, c.y + r},         {c.x - r - w, c.y - r - h}, {c.x - r - w, c.y + r}};
            for (const ChartPoint& o : options) {
                const ChartBox box{o.x, o.y, o.x + w, o.y + h};
                const bool inside =
                    box.x0 >= bounds.x0 && box.y0 >= bounds.y0 && box.x1 <= bounds.x1 && box.y1 <= bounds.y1;
                if (inside &&
                    std::none_of(taken.begin(), taken.end(), [&](const ChartBox& t) { return t.overlaps(box); })) {
                    found = o;
                    break;
                }
            }
            if (found) break;
        }
        if (found) taken.push_back({found->x, found->y, found->x + w, found->y + h});
        at.push_back(found);
    }
    return at;
}

std::string speed_accuracy_png(const BenchRun& run) {
    const int count = static_cast<int>(run.scenes.size());
    const int columns = std::clamp(count, 1, 4);
    const int rows = (count + columns - 1) / columns;
    const float panel_w = 470.0f, panel_h = 390.0f, header = 100.0f;
    // At least 960 pixels wide, so the header's lines fit above a single panel too.
    const int width = std::max(960, static_cast<int>(columns * panel_w + 20));
    const int height = static_cast<int>(header + rows * panel_h + 10);
    return draw_png(width, height, [&](ImDrawList& list) {
        text(list, {12, 8}, ink,
             "Speed against accuracy: time per step (recorder off, median) against each scene's error, log-log. "
             "Lower left is better.",
             17.0f);
        text(list, {12, 30}, faint,
             "Numbers beside the markers: the iteration count N. Filled: the run held; hollow: it failed. Moved "
             "aside: a thin line leads back.");
        text(list, {12, 49}, faint,
             "Grey line and rings: the Pareto front of the runs that held. Dashed: the scene's target. An error of 0 "
             "sits on the bottom edge.");
        float at = 12;
        for (std::size_t m = 0; m < run.methods.size(); ++m) {
            marker(list, method_style(run.methods, m).shape, {at + 6, 84}, method_style(run.methods, m).colour, true);
            text(list, {at + 16, 75}, ink, run.methods[m]);
            at += 34 + text_width(run.methods[m]);
        }
        for (int i = 0; i < count; ++i) {
            const ImVec2 origin{10 + static_cast<float>(i % columns) * panel_w,
                                header + static_cast<float>(i / columns) * panel_h};
            list.AddRect({origin.x + 2, origin.y + 2}, {origin.x + panel_w - 4, origin.y + panel_h - 6},
                         IM_COL32(225, 225, 225, 255));
            panel(list, origin, {panel_w, panel_h}, run, *run.scenes[static_cast<std::size_t>(i)]);
        }
    });
}

std::string stability_png(const BenchRun& run) {
    // Rows are the stress scenes and columns the methods: ten scenes and five methods fit a screen this way.
    const bench::StabilityMatrix m = bench::stability_matrix(run.rows, run.methods, run.scenes);
    const float left = 240.0f, cell_w = 282.0f, cell_h = 72.0f, top = 86.0f;
    const int width =
        static_cast<int>(left + cell_w * static_cast<float>(std::max<std::size_t>(1, m.methods.size())) + 20);
    const int height = static_cast<int>(top + cell_h * static_cast<float>(m.scenes.size()) + 44);
    return draw_png(width, height, [&](ImDrawList& list) {
        std::string counts;
        for (std::size_t i = 0; i < run.iterations.size(); ++i)
            counts += (i ? ", " : "") + std::to_string(run.iterations[i]);
        text(list, {12, 8}, ink, "Stability: each method on each stress scene at its largest N (of " + counts + ")",
             17.0f);
        text(list, {12, 30}, faint,
             "Green: meets the target. Amber: holds but misses the target (by how many times). Red: fails: why, "
             "when, metric. \"from N = k\": smaller N failed.");
        for (std::size_t i = 0; i < m.methods.size(); ++i)
            text(list, {left + cell_w * static_cast<float>(i) + 8, top - 26}, ink, m.methods[i], 17.0f);
        for (std::size_t j = 0; j < m.scenes.size(); ++j) {
            const BenchScene& spec = *m.scenes[j];
            const float Y = top + cell_h * static_cast<float>(j);
            text(list, {12, Y + 16}, ink, spec.name, 16.0f);
            text(list, {12, Y + 38}, faint,
                 std::string(bench::metric_name(spec.metric)) + " <= " + bench::metric_text(spec, spec.target));
            for (std::size_t i = 0; i < m.methods.size(); ++i) {
                const bench::StabilityCell& cell = m.cells[i][j];
                const ImVec2 a{left + cell_w * static_cast<float>(i), Y}, b{a.x + cell_w, Y + cell_h};
                // Three verdicts, three colours (and their words, for print and colour-blind readers).
                const ImU32 fill = !cell.ran           ? IM_COL32(235, 235, 235, 255)
                                   : !cell.holds       ? IM_COL32(248, 196, 196, 255)
                                   : cell.meets_target ? IM_COL32(198, 236, 198, 255)
                                                       : IM_COL32(252, 226, 170, 255);
                const ImU32 dark = !cell.ran           ? faint
                                   : !cell.holds       ? IM_COL32(170, 20, 20, 255)
                                   : cell.meets_target ? IM_COL32(20, 110, 20, 255)
                                                       : IM_COL32(140, 80, 0, 255);
                list.AddRectFilled({a.x + 2, a.y + 2}, {b.x - 2, b.y - 2}, fill);
                const float room = cell_w - 14;
                if (!cell.ran) {
                    text(list, {a.x + 8, a.y + 6}, faint, "not run");
                    continue;
                }
                text(list, {a.x + 8, a.y + 5}, dark,
                     std::string(bench::verdict_text(cell)) + "  (N = " + std::to_string(cell.n) + ")", 16.0f);
                std::string second,
                    third = std::string(bench::metric_name(spec.metric)) + " " + bench::metric_text(spec, cell.error);
                if (cell.holds) {
                    second =
                        cell.holds_from ? "held from N = " + std::to_string(*cell.holds_from) : "held at every N run";
                    if (!cell.meets_target && std::isfinite(cell.error) && spec.target > 0) {
                        char times[48];
                        std::snprintf(times, sizeof times, ", %.2g × the target", cell.error / spec.target);
                        second += times;
                    }
                } else {
                    char when[32];
                    std::snprintf(when, sizeof when, " at %.2f s", cell.failure_time.value_or(0.0));
                    second = cell.failure + when;
                }
                text(list, {a.x + 8, a.y + 26}, ink, fitted(second, room));
                text(list, {a.x + 8, a.y + 46}, ink, fitted(third, room));
            }
        }
        text(list, {12, static_cast<float>(height) - 28}, faint,
             "Metrics and thresholds: docs/bench.md. The isolated impacts (sphere_drop, two_spheres) have no verdict.");
    });
}

}  // namespace impulse::bench
