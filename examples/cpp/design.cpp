// The C example (examples/c/design.c) through the RAII wrapper lamella.hpp: designs a
// theta = 60 degree pseudo-geodesic field step by step.
//
// Usage: design_cpp OUT_DIR [MESH.obj]
// Reads MESH.obj or generates a parabolic vault, starts from the coordinate along the mesh's
// longest extent, steps until convergence printing progress, stores the session and restores
// it (as a CAD document would), and writes OUT_DIR/field.csv and OUT_DIR/binormals.csv.
#include "lamella.hpp"
#include "vault.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>

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

// The coordinate along the longest side of the bounding box, per vertex.
std::vector<double> initial_field(const std::vector<double> &xyz) {
    std::size_t n = xyz.size() / 3;
    std::array<double, 3> extent{};
    for (int k = 0; k < 3; ++k) {
        double lo = xyz[k], hi = xyz[k];
        for (std::size_t v = 0; v < n; ++v) {
            lo = std::min(lo, xyz[3 * v + k]);
            hi = std::max(hi, xyz[3 * v + k]);
        }
        extent[k] = hi - lo;
    }
    int axis = static_cast<int>(std::max_element(extent.begin(), extent.end()) - extent.begin());
    std::vector<double> field(n);
    for (std::size_t v = 0; v < n; ++v) {
        field[v] = xyz[3 * v + axis];
    }
    return field;
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
        lamella::Field field(mesh, initial_field(xyz), lamella::Field::pseudo_geodesic(60.0));
        std::cout << xyz.size() / 3 << " vertices, theta = 60 degrees\n";
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
        return 0;
    } catch (const std::exception &e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
}
