// The C example (examples/c/design.c) through the RAII wrapper lamella.hpp: designs a
// theta = 60 degree strip pattern step by step.
//
// Usage: design_cpp OUT_DIR [MESH.obj]
// Reads MESH.obj or generates a parabolic vault, lets the library's start search choose the
// initial field, steps until convergence printing progress, stores the session and restores it
// (as a CAD document would), writes OUT_DIR/field.csv and OUT_DIR/binormals.csv, then extracts
// level curves, builds rectifying strips on them, prints the verdict and writes
// OUT_DIR/curves.obj (polylines as `l` lines) and OUT_DIR/strips.obj (planar quads, one group
// per strip), with the same layout and numbers as the C example's files. Strips that miss theta
// are written all the same; the exit status is non-zero only on a failure.
#include "lamella.hpp"
#include "vault.h"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

lamella::Mesh load_mesh(int argc, char **argv) {
    if (argc > 2) {
        return lamella::Mesh::read_obj(argv[2]);
    }
    Vault vault;
    if (!vault_generate(&vault, 24)) {
        throw std::bad_alloc();
    }
    std::vector<double> xyz(vault.xyz, vault.xyz + 3 * vault.vertex_count);
    std::vector<std::uint32_t> triangles(vault.triangles, vault.triangles + 3 * vault.triangle_count);
    vault_free(&vault);
    return lamella::Mesh::from_arrays(xyz, triangles);
}

// The library's start search: every candidate probed and printed (`*` the winner), then the
// field that continues from the best one.
lamella::Field search_start(const lamella::Mesh &mesh, double theta_degrees) {
    lamella::Search search(mesh, lamella::Field::pseudo_geodesic(theta_degrees));
    while (search.step()) {
    }
    std::size_t count = search.candidate_count(), winner = search.winner();
    std::printf("start search: %lu candidates\n", static_cast<unsigned long>(count));
    for (std::size_t i = 0; i < count; ++i) {
        std::printf("%c candidate %lu: %s\n", i == winner ? '*' : ' ', static_cast<unsigned long>(i),
                    search.candidate_text(i).c_str());
    }
    return search.take_field();
}

// The verdict on the strips: the library's message when they miss theta, else the worst quad.
void print_verdict(const lamella::Strips &strips) {
    LmlVerdict verdict = strips.verdict();
    if (verdict.acceptable) {
        std::printf("verdict: acceptable, every strip within %.1f deg of theta (worst: strip %lu quad %lu, %.3f deg off)\n",
                    verdict.tolerance_degrees, static_cast<unsigned long>(verdict.worst_strip),
                    static_cast<unsigned long>(verdict.worst_quad), verdict.worst_error_degrees);
    } else {
        std::printf("verdict: %s\n", strips.verdict_message().c_str());
    }
}

void write_csv(const std::string &path, const char *header, const std::vector<double> &xyz,
               const std::vector<double> &values, std::size_t per_vertex) {
    std::ofstream out(path);
    out << header << '\n' << std::setprecision(17);
    for (std::size_t v = 0; v < xyz.size() / 3; ++v) {
        out << xyz[3 * v] << ',' << xyz[3 * v + 1] << ',' << xyz[3 * v + 2];
        for (std::size_t k = 0; k < per_vertex; ++k) {
            out << ',' << values[per_vertex * v + k];
        }
        out << '\n';
    }
    if (!out) {
        throw std::runtime_error("cannot write " + path);
    }
}

// OBJ vertices, formatted as the C example formats them (so the files can be compared).
void write_vertices(std::FILE *file, const std::vector<double> &xyz) {
    for (std::size_t v = 0; v + 2 < xyz.size(); v += 3) {
        std::fprintf(file, "v %.17g %.17g %.17g\n", xyz[v], xyz[v + 1], xyz[v + 2]);
    }
}

// Owns a FILE (closed on every path).
struct FileCloser {
    void operator()(std::FILE *file) const noexcept { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_for_writing(const std::string &path) {
    File file(std::fopen(path.c_str(), "w"));
    if (!file) {
        throw std::runtime_error("cannot write " + path);
    }
    return file;
}

void write_curves(const std::string &path, const lamella::Curves &curves) {
    File file = open_for_writing(path);
    std::vector<std::size_t> offsets = curves.offsets();
    write_vertices(file.get(), curves.points());
    for (std::size_t i = 0; i + 1 < offsets.size(); ++i) {
        std::fprintf(file.get(), "l");
        for (std::size_t p = offsets[i]; p < offsets[i + 1]; ++p) {
            std::fprintf(file.get(), " %lu", static_cast<unsigned long>(p) + 1);
        }
        std::fprintf(file.get(), "\n");
    }
}

void write_strips(const std::string &path, const lamella::Strips &strips) {
    File file = open_for_writing(path);
    std::vector<std::size_t> offsets = strips.quad_offsets();
    std::vector<std::uint32_t> quads = strips.quads();
    write_vertices(file.get(), strips.vertices());
    for (std::size_t i = 0; i + 1 < offsets.size(); ++i) {
        std::fprintf(file.get(), "g strip%lu\n", static_cast<unsigned long>(i));
        for (std::size_t j = offsets[i]; j < offsets[i + 1]; ++j) {
            const std::uint32_t *quad = &quads[4 * j];
            std::fprintf(file.get(), "f %u %u %u %u\n", quad[0] + 1, quad[1] + 1, quad[2] + 1, quad[3] + 1);
        }
    }
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " OUT_DIR [MESH.obj]\n";
        return 2;
    }
    try {
        std::cout << "lamella " << lml_version() << " (ABI " << lml_abi_version() << ")\n";
        lamella::Mesh mesh = load_mesh(argc, argv);
        std::vector<double> xyz = mesh.positions();
        std::cout << xyz.size() / 3 << " vertices, theta = 60 degrees\n";
        lamella::Field field = search_start(mesh, 60.0);
        LmlReport report{};
        bool converged = false;
        while (!converged && report.iterations < 300) {
            converged = field.step(5, report);
            std::printf("iteration %3lu: E_angle %.3e  max angle error %7.3f deg  singular vertices %lu\n",
                        static_cast<unsigned long>(report.iterations), report.energy_angle,
                        report.angle_error_max_degrees, static_cast<unsigned long>(report.singular_vertex_count));
        }
        if (!converged) {
            std::cerr << "not converged after " << report.iterations << " iterations\n";
            return 1;
        }
        // A CAD document would store these bytes and reopen the session later.
        std::vector<std::uint8_t> stored = field.save();
        lamella::Field reopened = lamella::Field::load(stored);
        std::cout << "converged after " << report.iterations << " iterations; session stored in "
                  << stored.size() << " bytes and reopened\n";
        std::string dir = argv[1];
        write_csv(dir + "/field.csv", "x,y,z,field", xyz, reopened.values(), 1);
        write_csv(dir + "/binormals.csv", "x,y,z,bx,by,bz", xyz, reopened.binormals(), 3);
        std::cout << "wrote " << dir << "/field.csv, " << dir << "/binormals.csv\n";

        // Six level curves resampled at 0.5, strips 0.4 wide (as the C example).
        lamella::Curves curves = lamella::Curves::uniform(reopened, 6, 0.5);
        lamella::Strips strips(curves, lamella::Strips::params(60.0, 0.4));
        print_verdict(strips);
        LmlPatternMetrics pattern = strips.pattern_metrics();
        std::printf("%lu strips, %lu curves skipped; max diff_theta %.3f deg, max e_straight %.1e\n",
                    static_cast<unsigned long>(pattern.strip_count), static_cast<unsigned long>(pattern.skipped_count),
                    pattern.max_diff_theta_degrees, pattern.max_e_straight);
        write_curves(dir + "/curves.obj", curves);
        write_strips(dir + "/strips.obj", strips);
        std::cout << "wrote " << dir << "/curves.obj, " << dir << "/strips.obj\n";
        return 0;
    } catch (const std::exception &e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
}
