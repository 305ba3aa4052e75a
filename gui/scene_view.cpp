#include "gui/panels.hpp"
#include "gui/text_wrap.hpp"

#include "explain/format.hpp"
#include "shapes/shape.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace impulse::gui {

namespace {

// World → pixels: rotate into the view (its x right, y up), scale, and flip y for the screen.
struct Projector {
    Mat3 view;  // rows: the view's right, up and towards-the-viewer axes in world coordinates
    Vec3 centre;
    ImVec2 origin;
    float scale;  // pixels per metre

    Vec3 in_view(const Vec3& p) const { return view * (p - centre); }
    ImVec2 operator()(const Vec3& p) const {
        const Vec3 q = in_view(p);
        return {origin.x + static_cast<float>(q.x()) * scale, origin.y - static_cast<float>(q.y()) * scale};
    }
};

Mat3 view_rotation(const SceneCamera& camera) {
    Mat3 m;
    switch (camera.plane) {
        case ViewPlane::front:  // x right, y up
            m << 1, 0, 0, 0, 1, 0, 0, 0, 1;
            return m;
        case ViewPlane::top:  // looking down: x right, -z up
            m << 1, 0, 0, 0, 0, -1, 0, 1, 0;
            return m;
        case ViewPlane::side:  // from +x: -z right, y up
            m << 0, 0, -1, 0, 1, 0, 1, 0, 0;
            return m;
        case ViewPlane::perspective:
            break;
    }
    const Mat3 yaw = Eigen::AngleAxisd(camera.yaw, Vec3::UnitY()).toRotationMatrix();
    const Mat3 pitch = Eigen::AngleAxisd(camera.pitch, Vec3::UnitX()).toRotationMatrix();
    return pitch * yaw;
}

// Draws each distinct segment and dot once. In a plane view, bodies in a row along the line of sight have
// coincident edges and contact points; drawing them once keeps the 1000-box grid cheap to rasterise.
class Pen {
public:
    explicit Pen(ImDrawList* draw) : draw_(draw) {}

    void line(ImVec2 a, ImVec2 b, ImU32 colour, float thickness) {
        if (std::abs(a.x - b.x) + std::abs(a.y - b.y) < 0.5f) return;  // an edge seen end-on is a point
        if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
        if (first_time(a, b, colour ^ static_cast<ImU32>(thickness * 8.0f))) draw_->AddLine(a, b, colour, thickness);
    }
    void dot(ImVec2 p, float radius, ImU32 colour) {
        if (first_time(p, ImVec2(radius, radius), colour))
            draw_->AddRectFilled(ImVec2(p.x - radius, p.y - radius), ImVec2(p.x + radius, p.y + radius), colour);
    }

private:
    bool first_time(ImVec2 a, ImVec2 b, ImU32 colour) {
        const auto q = [](float v) {
            return static_cast<std::uint64_t>(static_cast<std::uint16_t>(std::lround(v * 2.0f)));
        };
        const std::uint64_t key =
            (q(a.x) | q(a.y) << 16 | q(b.x) << 32 | q(b.y) << 48) ^ (colour * 0x9E3779B97F4A7C15ull);
        return seen_.insert(key).second;
    }

    ImDrawList* draw_;
    std::unordered_set<std::uint64_t> seen_;
};

Mat3 rotation_of(const BodyState& b) {
    return b.orientation.normalized().toRotationMatrix();
}

double radius_of(const Scene& scene, std::size_t body) {
    const std::optional<Shape>& shape = scene.shapes[body];
    return shape ? bounding_radius(*shape) : 0.05;
}

void arrow(ImDrawList* draw, ImVec2 from, ImVec2 to, ImU32 colour, float thickness) {
    const float dx = to.x - from.x, dy = to.y - from.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    draw->AddLine(from, to, colour, thickness);
    if (length < 1.0f) return;
    const float ux = dx / length, uy = dy / length, head = std::min(9.0f, length * 0.5f);
    draw->AddTriangleFilled(to, ImVec2(to.x - ux * head - uy * head * 0.5f, to.y - uy * head + ux * head * 0.5f),
                            ImVec2(to.x - ux * head + uy * head * 0.5f, to.y - uy * head - ux * head * 0.5f), colour);
}

void draw_body(Pen& pen, const Projector& project, const Scene& scene, std::size_t i, const BodyState& b, ImU32 colour,
               float thickness) {
    const Mat3 r = rotation_of(b);
    const std::optional<Shape>& shape = scene.shapes[i];
    if (shape && std::holds_alternative<Box>(*shape)) {
        const Vec3& half = std::get<Box>(*shape).half_size;
        ImVec2 corner[8];
        for (int v = 0; v < 8; ++v) corner[v] = project(b.position + r * box_vertex(half, v));
        // Hidden edges are left out: an edge shows when one of its two faces looks towards the viewer. A solid
        // box reads unambiguously in the 3D view, and a grid of a thousand boxes needs a quarter fewer lines.
        const Vec3 towards_viewer = project.view.row(2).transpose();
        const auto face_visible = [&](int axis, int vertex) {
            const double outward = (vertex & (1 << axis)) ? -1.0 : 1.0;  // box_vertex: a set bit is the - side
            return outward * r.col(axis).dot(towards_viewer) > -1e-9;
        };
        for (int v = 0; v < 8; ++v)
            for (int axis = 0; axis < 3; ++axis) {
                if (v & (1 << axis)) continue;
                const int b1 = (axis + 1) % 3, b2 = (axis + 2) % 3;
                if (face_visible(b1, v) || face_visible(b2, v))
                    pen.line(corner[v], corner[v | 1 << axis], colour, thickness);
            }
    } else if (shape) {
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const double radius = std::get<Sphere>(*shape).radius;
        const ImVec2 c = project(b.position);
        draw->AddCircle(c, static_cast<float>(radius) * project.scale, colour, 0, thickness);
        // A radius along the body's x axis shows the sphere turning.
        draw->AddLine(c, project(b.position + r * Vec3(radius, 0, 0)), colour, thickness);
    } else {
        // No shape (a case's body): its centre and axes.
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const ImVec2 c = project(b.position);
        for (int axis = 0; axis < 3; ++axis) {
            const Vec3 tip = b.position + r.col(axis) * (14.0 / project.scale);
            draw->AddLine(c, project(tip), colour, thickness);
        }
        draw->AddCircleFilled(c, 3.0f, colour);
    }
}

void draw_ground(ImDrawList* draw, const Projector& project, const HalfSpace& plane, const Vec3& near, double extent) {
    const Vec3 n = plane.normal.normalized();
    const Vec3 seed = std::abs(n.x()) > 0.9 ? Vec3::UnitY() : Vec3::UnitX();
    const Vec3 t1 = n.cross(seed).normalized(), t2 = n.cross(t1);
    const Vec3 centre = near - n * (n.dot(near) - plane.offset);  // `near` projected onto the plane
    const ImU32 colour = IM_COL32(120, 120, 110, 200);
    constexpr int lines = 8;
    for (int k = -lines; k <= lines; ++k) {
        const double s = extent * k / lines;
        draw->AddLine(project(centre + t1 * s - t2 * extent), project(centre + t1 * s + t2 * extent), colour, 1.0f);
        draw->AddLine(project(centre + t2 * s - t1 * extent), project(centre + t2 * s + t1 * extent), colour, 1.0f);
    }
}

// A bar of a round length (1, 2 or 5 × 10^k m) between 60 and 150 pixels.
void draw_scale_bar(ImDrawList* draw, ImVec2 at, float scale) {
    double metres = std::pow(10.0, std::floor(std::log10(100.0 / scale)));
    for (double step : {2.0, 2.5, 2.0})
        if (metres * scale < 60.0) metres *= step;
    const float pixels = static_cast<float>(metres * scale);
    draw->AddLine(at, ImVec2(at.x + pixels, at.y), IM_COL32(220, 220, 220, 255), 2.0f);
    draw->AddText(ImVec2(at.x, at.y - 17.0f), IM_COL32(220, 220, 220, 255), (explain::number(metres) + " m").c_str());
}

}  // namespace

void draw_scene_view(const model::Session& session, UiState& state) {
    SceneCamera& camera = state.camera;
    const char* planes[] = {"Front (x, y)", "Top (x, z)", "Side (z, y)", "3D (drag to turn)"};
    // The view buttons flow onto a second line when the panel is too narrow for one (1024 px wide).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
    const auto same_line_if_fits = [&](float width) {
        ImGui::SameLine();
        if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
    };
    for (int p = 0; p < 4; ++p) {
        if (p > 0)
            same_line_if_fits(ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(planes[p]).x);
        if (ImGui::RadioButton(planes[p], camera.plane == static_cast<ViewPlane>(p)))
            camera.plane = static_cast<ViewPlane>(p);
    }
    same_line_if_fits(ImGui::CalcTextSize("Fit").x + style.FramePadding.x * 2);
    if (ImGui::Button("Fit")) camera.zoom = 1.0f, camera.pan_x = camera.pan_y = 0.0f;

    const CursorViews& v = state.views;
    const ImVec2 top_left = ImGui::GetCursorScreenPos();
    const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 50.0f),
                      std::max(ImGui::GetContentRegionAvail().y, 50.0f));
    ImGui::InvisibleButton("canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) camera.zoom *= std::pow(1.15f, io.MouseWheel);
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        if (camera.plane == ViewPlane::perspective)
            camera.yaw += io.MouseDelta.x * 0.01f,
                camera.pitch = std::clamp(camera.pitch + io.MouseDelta.y * 0.01f, -1.5f, 1.5f);
        else
            camera.pan_x += io.MouseDelta.x, camera.pan_y += io.MouseDelta.y;
    }
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Right))
        camera.pan_x += io.MouseDelta.x, camera.pan_y += io.MouseDelta.y;

    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 bottom_right(top_left.x + size.x, top_left.y + size.y);
    draw->AddRectFilled(top_left, bottom_right, IM_COL32(24, 26, 32, 255));
    draw->PushClipRect(top_left, bottom_right, true);
    if (!v.cursor) {
        draw->AddText(ImVec2(top_left.x + 10, top_left.y + 10), IM_COL32(200, 200, 200, 255), "nothing recorded");
        draw->PopClipRect();
        return;
    }
    const Trace& trace = session.trace();
    const Scene& scene = trace.scene;
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(v.cursor->frame)];
    // A lesson's open question hides the bodies a hidden change moved: each is drawn where it was last
    // shown, without the move or its velocities.
    const course::Mask& mask = state.mask;
    std::vector<BodyState> after = v.bodies.after, before_shown = v.bodies.before;
    std::vector<char> concealed(after.size(), 0);
    for (std::size_t b = 0; b < after.size(); ++b) {
        const int body = static_cast<int>(b);
        if (mask.hides_body(*v.cursor, body, false, v.bodies.before[b])) {
            // Where a hidden change left it last shown; a body hidden only for its values (equal to an
            // answer) is drawn where it is, without its values anywhere.
            const std::optional<model::Cursor> until = mask.body_shown_until(*v.cursor, body);
            const BodyState last = !until                            ? v.bodies.before[b]
                                   : until->frame == v.cursor->frame ? model::bodies_at(trace, *until).before[b]
                                                                     : frame.bodies_before[b];
            after[b] = before_shown[b] = last;
            concealed[b] = 1;
        } else if (mask.hides_body(*v.cursor, body, true, v.bodies.after[b])) {
            after[b] = v.bodies.before[b];
            concealed[b] = 1;
        }
    }
    std::vector<int> moved_bodies;
    for (int b : v.bodies.moved)
        if (!concealed[static_cast<std::size_t>(b)]) moved_bodies.push_back(b);

    // The legend, wrapped to the canvas (a lesson's scene is narrow), over the top of it; the bodies are fitted
    // into the part below it and above the scale bar, so the legend never covers them.
    std::string legend;
    for (const std::string& line :
         wrap_lines("orange: moved by this item (faint: before) · green: normal · red: penetration · violet: impulse "
                    "so far · magenta: this impulse · blue: velocity × 0.1 s",
                    size.x - 24.0f))
        legend += (legend.empty() ? "" : "\n") + line;
    const float legend_bottom = top_left.y + 6 + ImGui::CalcTextSize(legend.c_str()).y;
    const float fit_top = std::min(legend_bottom + 4, top_left.y + size.y / 2);
    const float fit_bottom = std::max(bottom_right.y - 24, fit_top + 25);

    // Fit the bodies (and contact points) into the canvas.
    Projector project{view_rotation(camera), Vec3::Zero(), ImVec2(), 1.0f};
    Vec3 low = Vec3::Constant(1e300), high = Vec3::Constant(-1e300);
    for (std::size_t i = 0; i < after.size(); ++i) {
        const Vec3 q = project.in_view(after[i].position);
        const double r = radius_of(scene, i);
        low = low.cwiseMin(q - Vec3::Constant(r));
        high = high.cwiseMax(q + Vec3::Constant(r));
    }
    for (const model::ContactRow& row : v.contacts) {
        const Vec3 q = project.in_view(row.prepared->point);
        low = low.cwiseMin(q), high = high.cwiseMax(q);
    }
    if (after.empty()) low = Vec3::Constant(-1), high = Vec3::Constant(1);
    const Vec3 mid_view = (low + high) / 2;
    project.centre = project.view.transpose() * mid_view;
    const double span_x = std::max(high.x() - low.x(), 0.2), span_y = std::max(high.y() - low.y(), 0.2);
    project.scale =
        static_cast<float>(std::min(size.x / span_x, (fit_bottom - fit_top) / span_y)) * 0.85f * camera.zoom;
    project.origin = ImVec2(top_left.x + size.x / 2 + camera.pan_x, (fit_top + fit_bottom) / 2 + camera.pan_y);

    const double extent = std::max(span_x, span_y) * 0.75;
    if (scene.ground) {
        draw_ground(draw, project, scene.ground->plane, project.centre, extent);
    } else {
        // A case's contacts with the world (body 1) touch a surface the file does not describe as a shape:
        // drawn as a plane through each contact point across its normal, once per distinct plane.
        std::vector<HalfSpace> planes;
        for (const model::ContactRow& row : v.contacts) {
            if (row.prepared->bodies[1] != world_body || planes.size() >= 8) continue;
            const HalfSpace plane{row.prepared->normal, row.prepared->normal.dot(row.prepared->point)};
            const bool seen = std::any_of(planes.begin(), planes.end(), [&](const HalfSpace& p) {
                return p.normal.isApprox(plane.normal, 1e-9) && std::abs(p.offset - plane.offset) < 1e-9;
            });
            if (seen) continue;
            planes.push_back(plane);
            draw_ground(draw, project, plane, row.prepared->point, extent);
        }
    }

    // Bodies: moved ones in orange, with a faint ghost where they were before this item's move.
    std::vector<char> moved(after.size(), 0);
    for (int b : moved_bodies) moved[static_cast<std::size_t>(b)] = 1;
    const bool position_move = v.cursor->stage == model::Stage::position;
    Pen pen(draw);
    for (std::size_t i = 0; i < after.size(); ++i) {
        if (moved[i] && position_move)
            draw_body(pen, project, scene, i, before_shown[i], IM_COL32(255, 170, 60, 90), 1.0f);
        // Whole-pixel widths: ImGui draws those from its texture, one quad per line, which keeps a
        // thousand boxes cheap to rasterise.
        draw_body(pen, project, scene, i, after[i],
                  moved[i] ? IM_COL32(255, 170, 60, 255) : IM_COL32(150, 170, 205, 255), moved[i] ? 2.0f : 1.0f);
    }
    // Velocity phase: each changed body's velocity before (faint) and after, as the distance it covers in 0.1 s.
    if (v.cursor->stage == model::Stage::velocity)
        for (int b : moved_bodies) {
            const auto i = static_cast<std::size_t>(b);
            arrow(draw, project(after[i].position), project(after[i].position + before_shown[i].velocity * 0.1),
                  IM_COL32(120, 200, 255, 110), 2.0f);
            arrow(draw, project(after[i].position), project(after[i].position + after[i].velocity * 0.1),
                  IM_COL32(120, 200, 255, 255), 2.0f);
        }

    // Contacts: penetration depth in red along -n, impulse so far in violet, status by colour.
    const int current = model::contact_at(trace, *v.cursor);
    const float impulse_pixels = 70.0f;
    // In a crowded frame (the 1000-box grid has 4000 contacts) arrows and dots at every contact hide the
    // bodies: then only the current contact and the contacts sharing one of its bodies get theirs (the
    // contacts list still shows every status).
    constexpr std::size_t crowded = 200;
    std::vector<char> shares_body(after.size() + 1, 0);
    if (const ContactPreparation* c = model::preparation_of(frame, current))
        for (int b : c->bodies)
            if (b != world_body) shares_body[static_cast<std::size_t>(b)] = 1;
    const auto near_current = [&](const ContactPreparation& c) {
        for (int b : c.bodies)
            if (b != world_body && shares_body[static_cast<std::size_t>(b)]) return true;
        return false;
    };
    double current_penetration = 0.0;
    for (const model::ContactRow& row : v.contacts) {
        const ContactPreparation& c = *row.prepared;
        if (c.contact == current) current_penetration = row.penetration;
        const ImVec2 p = project(c.point);
        // A depth under a pixel and a half is invisible at this zoom: not drawn; nor one a question hides.
        if (row.penetration * project.scale > 1.5 &&
            !mask.hides_value(*v.cursor, c.contact, "penetration", row.penetration))
            pen.line(p, project(c.point - c.normal * row.penetration), IM_COL32(240, 70, 60, 255), 2.0f);
        const bool show_arrow = (v.contacts.size() <= crowded || near_current(c)) &&
                                !mask.hides_value(*v.cursor, c.contact, "impulse_world", row.impulse_so_far.norm());
        if (show_arrow && v.largest_impulse > 0 && row.impulse_so_far.norm() > 0) {
            const Vec3 direction = project.view * row.impulse_so_far;
            const float k = impulse_pixels / static_cast<float>(v.largest_impulse);
            arrow(draw, p,
                  ImVec2(p.x + static_cast<float>(direction.x()) * k, p.y - static_cast<float>(direction.y()) * k),
                  IM_COL32(190, 120, 255, 200), 1.0f);
        }
        const ImU32 colour = row.status == model::ContactStatus::chosen    ? IM_COL32(255, 230, 60, 255)
                             : row.status == model::ContactStatus::waiting ? IM_COL32(240, 130, 60, 255)
                                                                           : IM_COL32(130, 190, 130, 255);
        // Small squares: two triangles each, for scenes with thousands of contacts.
        if (v.contacts.size() <= crowded || row.status == model::ContactStatus::chosen || near_current(c))
            pen.dot(p, c.contact == current ? 4.0f : 2.0f, colour);
    }
    // The current contact: ringed, with its normal and, in the velocity phase, this iteration's impulse.
    if (const ContactPreparation* c = model::preparation_of(frame, current)) {
        const ImVec2 p = project(c->point);
        draw->AddCircle(p, 9.0f, IM_COL32(255, 230, 60, 255), 0, 2.0f);
        // The normal, unless a lesson's open question hides it (which way the engine turned a contact).
        explain::Row normal_row;
        normal_row.key = "normal";
        if (!mask.hides_row(*v.cursor, normal_row)) {
            const Vec3 n = project.view * c->normal;
            arrow(draw, p, ImVec2(p.x + static_cast<float>(n.x()) * 45.0f, p.y - static_cast<float>(n.y()) * 45.0f),
                  IM_COL32(90, 225, 120, 255), 2.0f);
        }
        if (v.cursor->stage == model::Stage::velocity) {
            const VelocityIteration& it = frame.velocity.iterations[static_cast<std::size_t>(v.cursor->item)];
            explain::Row impulse_row;
            impulse_row.key = "impulse_world";
            if (it.resolution && v.largest_impulse > 0 && !mask.hides_row(*v.cursor, impulse_row)) {
                const Vec3 g = project.view * it.resolution->impulse_terms.impulse_world;
                const float k = impulse_pixels / static_cast<float>(v.largest_impulse);
                arrow(draw, p, ImVec2(p.x + static_cast<float>(g.x()) * k, p.y - static_cast<float>(g.y()) * k),
                      IM_COL32(255, 80, 220, 255), 3.0f);
            }
        }
        const std::string label = mask.hides_value(*v.cursor, current, "penetration", current_penetration)
                                      ? "contact " + std::to_string(current)
                                      : "contact " + std::to_string(current) + " · penetration " +
                                            explain::number(current_penetration, std::abs(c->penetration)) + " m";
        // Beside the point, or to its left where the canvas ends.
        const float label_width = ImGui::CalcTextSize(label.c_str()).x;
        const float x = p.x + 12 + label_width > bottom_right.x - 4 ? p.x - 12 - label_width : p.x + 12;
        draw->AddText(ImVec2(std::max(x, top_left.x + 4), p.y - 22), IM_COL32(255, 230, 60, 255), label.c_str());
    }

    draw_scale_bar(draw, ImVec2(top_left.x + 12, bottom_right.y - 14), project.scale);
    draw->AddText(ImVec2(top_left.x + 12, top_left.y + 6), IM_COL32(180, 180, 180, 255), legend.c_str());
    if (!v.bodies.exact)
        draw->AddText(ImVec2(top_left.x + 12, legend_bottom + 2), IM_COL32(255, 120, 100, 255),
                      "bodies shown at the frame's start and end: the recording's contact filter left out a move");
    draw->PopClipRect();
}

}  // namespace impulse::gui
