#include "trajectory.hpp"

#include <fmt/core.h>

#include <fstream>
#include <limits>
#include <ostream>
#include <string>

#include "workbook/quaternion.hpp"
#include "workbook/time_series.hpp"
#include "workbook/world.hpp"

namespace workbook::sim {

namespace {

// A responder is a plain function pointer, so the impulse it gives is measured by a
// stand-in with the same signature that calls it and compares body 1's momentum along the
// normal before and after. The stand-in has no closure; it finds the real responder and its
// tally here. workbook-sim runs one world at a time on one thread.
struct ImpulseTally {
    VelocityResponder real = nullptr;
    std::vector<double> impulses;  // one per respond() call of the current step, in contact order
};
ImpulseTally tally;

void measuring_responder(RigidBody& body1, RigidBody& body2, const Contact& contact) {
    const Vector3 v1 = body1.velocity;
    const Vector3 v2 = body2.velocity;
    tally.real(body1, body2, contact);
    // J n acts on body 1 and -J n on body 2; read J off whichever body can move.
    const double impulse = !body1.is_immovable() ? body1.mass() * dot(body1.velocity - v1, contact.normal)
                           : !body2.is_immovable() ? -body2.mass() * dot(body2.velocity - v2, contact.normal)
                                                    : 0.0;
    tally.impulses.push_back(impulse);
}

// Body names are free text: quote them the CSV way (RFC 4180) when they need it.
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

void write_frame(std::ostream& out, std::size_t step, const World& world, const Scene& scene) {
    const auto bodies = world.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        out << step << ',' << world.time() << ',' << i << ',' << csv_field(scene.body_names[i]) << ','
            << b.position.x << ',' << b.position.y << ',' << b.position.z << ',' << b.orientation.w << ','
            << b.orientation.x << ',' << b.orientation.y << ',' << b.orientation.z << ',' << b.velocity.x << ','
            << b.velocity.y << ',' << b.velocity.z << ',' << b.angular_velocity.x << ',' << b.angular_velocity.y
            << ',' << b.angular_velocity.z;
        // The body's own axes in the world frame (the columns of its rotation matrix, the
        // engine's to_matrix()): what the pictures need to draw a box's corners and axes, a
        // plane's trace and a spin in the body frame, so that plots/ has no geometry of its own.
        const Matrix3 axes = to_matrix(b.orientation);
        for (int column = 0; column < 3; ++column)
            out << ',' << axes(0, column) << ',' << axes(1, column) << ',' << axes(2, column);
        out << '\n';
    }
}

/// The impulse of point `p` of contact `c` this step: the tally of the responder's calls, or,
/// for a model with a contact solver (chapter 5), the point's accumulated normal impulse.
double impulse_of(const World& world, std::size_t c, std::size_t p, bool responded) {
    if (world.model().contact_solver != nullptr) {
        const auto impulses = world.contact_solver().impulses();
        return c < impulses.size() ? impulses[c].points[p].normal : 0.0;
    }
    return responded ? tally.impulses[c] : 0.0;
}

void write_contacts(std::ostream& out, std::size_t step, const World& world, bool responded) {
    const auto contacts = world.contacts();
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Contact& contact = contacts[c];
        for (std::size_t p = 0; p < contact.point_count; ++p) {
            const ContactPoint& point = contact.points[p];
            out << step << ',' << world.time() << ',' << contact.body1 << ',' << contact.body2 << ',' << p << ','
                << point.position.x << ',' << point.position.y << ',' << point.position.z << ','
                << contact.normal.x << ',' << contact.normal.y << ',' << contact.normal.z << ',' << point.penetration
                << ',' << impulse_of(world, c, p, responded) << '\n';
        }
    }
}

// Full round-trip precision in the shortest form, restored on the way out.
class RoundTripFormat {
public:
    explicit RoundTripFormat(std::ostream& out)
        : out_(out), flags_(out.flags()), precision_(out.precision(std::numeric_limits<double>::max_digits10)) {
        out.unsetf(std::ios::floatfield);
    }
    ~RoundTripFormat() {
        out_.precision(precision_);
        out_.flags(flags_);
    }
    RoundTripFormat(const RoundTripFormat&) = delete;
    RoundTripFormat& operator=(const RoundTripFormat&) = delete;

private:
    std::ostream& out_;
    std::ios::fmtflags flags_;
    std::streamsize precision_;
};

}  // namespace

const char* trajectory_header() {
    return "frame,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,ex_x,ex_y,ex_z,ey_x,ey_y,ey_z,ez_x,ez_y,ez_z";
}

const char* contacts_header() {
    return "frame,t,body1,body2,point,x,y,z,nx,ny,nz,depth,impulse";
}

std::vector<Probes> run_recording(const Scene& scene, const ResponseModel& model, std::size_t stride,
                                  std::ostream& bodies, std::ostream& contacts) {
    const RoundTripFormat bodies_format(bodies);
    const RoundTripFormat contacts_format(contacts);
    const std::size_t steps = step_count(scene.duration, scene.settings.time_step);
    if (stride == 0) stride = 1;

    // The scene's world with the measuring stand-in in the responder's place; nothing else differs.
    tally = {model.respond, {}};
    World measured = make_world(scene, {model.name, model.respond != nullptr ? &measuring_responder : nullptr,
                                        model.correct, model.contact_solver});

    bodies << trajectory_header() << '\n';
    contacts << contacts_header() << '\n';
    std::vector<Probes> samples;
    samples.reserve(steps + 1);
    samples.push_back(measured.probes());
    write_frame(bodies, 0, measured, scene);
    for (std::size_t step = 1; step <= steps; ++step) {
        tally.impulses.clear();
        measured.step();
        samples.push_back(measured.probes());
        write_contacts(contacts, step, measured, model.respond != nullptr);
        if (step % stride == 0 || step == steps) write_frame(bodies, step, measured, scene);
    }
    return samples;
}

std::string contacts_path_for(const std::string& trajectory_path) {
    const std::string_view ext = ".csv";
    const bool has_ext = trajectory_path.size() > ext.size() && trajectory_path.ends_with(ext);
    return trajectory_path.substr(0, has_ext ? trajectory_path.size() - ext.size() : trajectory_path.size()) +
           ".contacts.csv";
}

std::optional<std::vector<Probes>> simulate(const Scene& scene, const std::string& trajectory_path, std::size_t stride) {
    const ResponseModel& model = *find_response_model(scene.responder);
    if (trajectory_path.empty()) {
        World world = make_world(scene, model);
        return run(world, scene.duration);
    }
    const std::string contacts_path = contacts_path_for(trajectory_path);
    std::ofstream bodies(trajectory_path);
    std::ofstream contacts(contacts_path);
    if (!bodies || !contacts) {
        fmt::print(stderr, "error: cannot write {}\n", !bodies ? trajectory_path : contacts_path);
        return std::nullopt;
    }
    auto samples = run_recording(scene, model, stride, bodies, contacts);
    if (!bodies.flush() || !contacts.flush()) {
        fmt::print(stderr, "error: writing {} or {} failed\n", trajectory_path, contacts_path);
        return std::nullopt;
    }
    return samples;
}

}  // namespace workbook::sim
