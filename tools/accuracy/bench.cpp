#include "bench.hpp"

#include <fmt/core.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <ctime>
#include <limits>
#include <ostream>

#include "stress.hpp"

namespace workbook::accuracy {

double seconds_per_run(const std::function<void()>& run) {
    // Processor time (std::clock) leaves out the time other users of a shared machine take;
    // batches make its coarse ticks small against what is measured.
    double best = std::numeric_limits<double>::infinity();
    for (int batch = 0; batch < 3; ++batch) {
        const std::clock_t start = std::clock();
        std::clock_t now = start;
        int runs = 0;
        while (now - start < CLOCKS_PER_SEC / 100) {
            run();
            ++runs;
            now = std::clock();
        }
        best = std::min(best, static_cast<double>(now - start) / CLOCKS_PER_SEC / runs);
    }
    return best;
}

const char* integrator_name(Integrator integrator) {
    switch (integrator) {
        case Integrator::semi_implicit_euler: return "semi-implicit-euler";
        case Integrator::explicit_euler: return "explicit-euler";
        case Integrator::exact_under_gravity: return "exact-under-gravity";
    }
    return "?";
}

const char* timing_name(ContactTiming timing) { return timing == ContactTiming::event ? "event" : "discrete"; }

std::vector<int> frame_rates() {
    std::vector<int> rates;
    for (int frames_per_second = 30; frames_per_second <= 3840; frames_per_second *= 2) rates.push_back(frames_per_second);
    return rates;
}

std::vector<BenchPoint> sweep(const Family& family) {
    std::vector<Integrator> integrators{Integrator::exact_under_gravity};
    if (family.gravity) integrators.insert(integrators.begin(), Integrator::semi_implicit_euler);
    std::vector<ContactTiming> timings{ContactTiming::discrete};
    if (family.contacts) timings.push_back(ContactTiming::event);
    std::vector<BenchPoint> points;
    for (int frames_per_second : frame_rates())
        for (int substeps : {1, 2, 4}) {
            if (frames_per_second * substeps > 3840) continue;
            for (Integrator integrator : integrators)
                for (ContactTiming timing : timings) {
                    BenchPoint point;
                    point.family = family.id;
                    point.frame_step = 1.0 / frames_per_second;
                    point.substeps = substeps;
                    point.integrator = integrator;
                    point.timing = timing;
                    WorldSettings settings;
                    settings.time_step = point.frame_step / substeps;
                    settings.integrator = integrator;
                    settings.contact_timing = timing;
                    settings.check_finite = false;
                    point.result = family.run(settings, family.model);
                    point.seconds = seconds_per_run([&] { (void)family.run(settings, family.model); });
                    points.push_back(point);
                }
        }
    mark_pareto_front(points);
    return points;
}

EventCost measure_event_cost(const Family& family, double time_step) {
    EventCost cost;
    cost.time_step = time_step;
    cost.discrete_ns_per_step = cost.event_ns_per_step = std::numeric_limits<double>::infinity();
    for (int round = 0; round < 5; ++round)
        for (ContactTiming timing : {ContactTiming::discrete, ContactTiming::event}) {
            WorldSettings settings;
            settings.time_step = time_step;
            settings.integrator = Integrator::exact_under_gravity;
            settings.contact_timing = timing;
            settings.check_finite = false;
            const double steps = static_cast<double>(family.run(settings, family.model).steps);
            const double ns = seconds_per_run([&] { (void)family.run(settings, family.model); }) / steps * 1e9;
            double& best = timing == ContactTiming::event ? cost.event_ns_per_step : cost.discrete_ns_per_step;
            best = std::min(best, ns);
        }
    return cost;
}

void mark_pareto_front(std::vector<BenchPoint>& points) {
    std::vector<BenchPoint*> by_time;
    for (BenchPoint& p : points)
        if (p.engine == "workbook") by_time.push_back(&p);
    std::sort(by_time.begin(), by_time.end(), [](const BenchPoint* a, const BenchPoint* b) {
        return a->seconds != b->seconds ? a->seconds < b->seconds : a->result.error < b->result.error;
    });
    double best = std::numeric_limits<double>::infinity();
    for (BenchPoint* p : by_time) {
        p->pareto = p->result.error < best;
        best = std::min(best, p->result.error);
    }
}

void write_bench_csv(std::ostream& out, const std::vector<BenchPoint>& points) {
    // Peers choose their own integrator and contact timing; their columns say "own".
    out << "family,engine,frame_step,substeps,time_step,integrator,timing,steps,seconds,error,bounce_time_error,pareto\n";
    for (const BenchPoint& p : points) {
        const bool peer = p.engine != "workbook";
        fmt::print(out, "{},{},{:.17g},{},{:.17g},{},{},{},{:.6g},{:.17g},{:.17g},{}\n", p.family, p.engine, p.frame_step,
                   p.substeps, p.frame_step / p.substeps, peer ? "own" : integrator_name(p.integrator),
                   peer ? "own" : timing_name(p.timing), p.result.steps, p.seconds, p.result.error, p.result.time_error,
                   p.pareto ? 1 : 0);
    }
}

GuardCost measure_guard_cost(const ResponseModel& model, const std::string& scene_name, int steps) {
    GuardCost cost;
    cost.scene = scene_name;
    for (const StressScene& scene : stress_corpus(false)) {
        if (scene.name != scene_name) continue;
        const World built = scene.build(model);
        cost.bodies = built.bodies().size();
        const std::vector<RigidBody> bodies(built.bodies().begin(), built.bodies().end());
        // On and off alternate, five times each, and each keeps its fastest: the machine's load
        // then falls on both alike.
        cost.on_ns = cost.off_ns = std::numeric_limits<double>::infinity();
        for (int round = 0; round < 5; ++round)
            for (bool on : {true, false}) {
                WorldSettings settings = built.settings();
                settings.check_finite = on;
                World world(bodies, settings, model);
                const std::clock_t start = std::clock();
                for (int i = 0; i < steps; ++i) world.step();
                const double ns = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC / steps * 1e9;
                double& best = on ? cost.on_ns : cost.off_ns;
                best = std::min(best, ns);
            }
    }
    return cost;
}

}  // namespace workbook::accuracy
