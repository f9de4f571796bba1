#include "step08_wakes/plan_view.hpp"

#include "step08_wakes/kelvin.hpp"

namespace step08 {

void PlanView::declare(ocean::ParamRegistry& p) {
    const auto group = p.group("from above");
    p.add_float("boat_speed", &boat_.speed, 0, 12, "from above: the boat's speed, metres per second");
    p.add_float("draft", &boat_.draft, 0, 2, "from above: how deep the hull presses the water at its middle, metres");
    p.add_float("rudder", &rudder_, -1, 1, "from above: the rudder, -1 (port) to 1 (starboard); the arrows add to it");
    p.add_float("relief", &relief_, 1, 50, "from above: how many times the shading exaggerates the slopes").logarithmic();
    p.add_bool("kelvin_lines", &kelvin_lines_, "from above: Kelvin's edges, 19.47 degrees either side of the track");
    p.add_bool("show_field", &show_field_, "from above: outline the field's grid and its absorbing layer");
}

void PlanView::init(ocean::ProgramFactory programs) {
    programs_ = std::move(programs);
    program();
}

ocean::ShaderProgram* PlanView::program() const {
    return programs_("wake", {"common/shaders/fullscreen.vert", "step08_wakes/shaders/wake.frag"}, {});
}

void PlanView::update(double dt, const WaveFieldSettings& field, double boat_length, double warm_up,
                      double extra_rudder) {
    boat_.length = boat_length;
    if (!scene_ || !same_grid(field, scene_->field().settings())) {
        scene_ = std::make_unique<WakeScene>(field);
        scene_->sail(warm_up, boat_, rudder_);  // the window opens on a wake already made
    }
    scene_->sail(dt, boat_, double(rudder_) + extra_rudder);
}

void PlanView::drop_stone(glm::dvec2 at, double impulse) {
    if (scene_) scene_->drop_stone(at, impulse);
}

glm::dvec2 PlanView::view_centre() const {
    const WaveField& f = scene_->field();
    return 0.5 * (f.cell_centre(0, 0) + f.cell_centre(f.n() - 1, f.n() - 1));
}

glm::dvec2 PlanView::half_view(float aspect) const {
    const double half = 0.5 * scene_->field().side();
    return {half * double(aspect), half};
}

glm::dvec2 PlanView::to_world(glm::dvec2 uv, float aspect) const {
    if (!scene_) return glm::dvec2(0.0);
    return view_centre() + (2.0 * uv - 1.0) * half_view(aspect);
}

void PlanView::draw(float aspect, int pixels_high, GLuint fullscreen_vao) {
    if (!scene_) return;
    const WaveField& f = scene_->field();
    if (heights_.id() == 0 || texture_cells_ != f.n()) {
        heights_ = ocean::make_float_texture_2d(GL_R32F, f.n(), f.n());
        texture_cells_ = f.n();
    }
    upload_.assign(f.heights().begin(), f.heights().end());
    ocean::upload_float_texture_2d(heights_, GL_R32F, f.n(), f.n(), upload_.data());
    ocean::ShaderProgram* p = program();
    if (p == nullptr) return;
    const glm::dvec2 centre = view_centre();
    p->set("u_cells", f.n());
    p->set("u_cell", float(f.settings().cell));
    p->set("u_first_cell", glm::vec2(f.cell_centre(0, 0) - centre));
    p->set("u_half_view", glm::vec2(half_view(aspect)));
    p->set("u_boat", glm::vec2(scene_->boat_position() - centre));
    p->set("u_heading", glm::vec2(scene_->boat_heading()));
    p->set("u_boat_length", float(boat_.length));
    p->set("u_relief", relief_);
    p->set("u_kelvin", kelvin_lines_ ? 1.0f : 0.0f);
    p->set("u_kelvin_angle", float(kelvin_edge_angle(0.5)));  // deep water: c_g = c / 2
    p->set("u_pixels_high", float(pixels_high));
    p->set("u_show_field", show_field_ ? 1.0f : 0.0f);
    p->set("u_absorbing_width", float(f.settings().absorbing_width));
    ocean::bind_texture(0, GL_TEXTURE_2D, heights_.id());
    glUseProgram(p->id());
    glBindVertexArray(fullscreen_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace step08
