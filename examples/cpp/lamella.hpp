// A thin RAII layer over Lamella's C ABI (include/lamella.h), showing how a C++ CAD
// integration holds the handles: each handle lives in a std::unique_ptr with a custom
// deleter, and every failing status becomes a lamella::Error carrying the library's message.
#ifndef LAMELLA_HPP
#define LAMELLA_HPP

#include "lamella.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lamella {

// A failed call: the status and the library's message (copied, so it outlives later calls).
class Error : public std::runtime_error {
public:
    Error(LmlStatus status, const std::string &call)
        : std::runtime_error(call + ": " + lml_status_name(status) + ": " + lml_last_error_message()),
          status_(status) {}
    LmlStatus status() const { return status_; }

private:
    LmlStatus status_;
};

// Passes successes (OK, MORE, CONVERGED, NO_ACCEPTABLE_FAMILY) through and throws on failures.
inline LmlStatus check(LmlStatus status, const char *call) {
    if (status < 0) {
        throw Error(status, call);
    }
    return status;
}

struct MeshDeleter {
    void operator()(LmlMesh *mesh) const noexcept { lml_mesh_free(mesh); }
};
struct FieldDeleter {
    void operator()(LmlField *field) const noexcept { lml_field_free(field); }
};
struct CurvesDeleter {
    void operator()(LmlCurves *curves) const noexcept { lml_curves_free(curves); }
};
struct StripsDeleter {
    void operator()(LmlStrips *strips) const noexcept { lml_strips_free(strips); }
};
struct SearchDeleter {
    void operator()(LmlSearch *search) const noexcept { lml_search_free(search); }
};
using MeshHandle = std::unique_ptr<LmlMesh, MeshDeleter>;
using FieldHandle = std::unique_ptr<LmlField, FieldDeleter>;
using CurvesHandle = std::unique_ptr<LmlCurves, CurvesDeleter>;
using StripsHandle = std::unique_ptr<LmlStrips, StripsDeleter>;
using SearchHandle = std::unique_ptr<LmlSearch, SearchDeleter>;

// The two-call pattern: asks for the size, then fills a vector of exactly that size.
template <class T, class Get>
std::vector<T> fetch(Get get, const char *call) {
    std::size_t needed = 0;
    LmlStatus status = get(nullptr, 0, &needed);
    if (status != LML_STATUS_BUFFER_TOO_SMALL) {
        check(status, call);
    }
    std::vector<T> out(needed);
    check(get(out.data(), out.size(), &needed), call);
    return out;
}

class Mesh {
public:
    static Mesh from_arrays(const std::vector<double> &xyz, const std::vector<std::uint32_t> &triangles) {
        LmlMesh *raw = nullptr;
        check(lml_mesh_new(xyz.data(), xyz.size() / 3, triangles.data(), triangles.size() / 3, &raw), "lml_mesh_new");
        return Mesh(MeshHandle(raw));
    }
    static Mesh read_obj(const std::string &path) {
        LmlMesh *raw = nullptr;
        check(lml_mesh_read_obj(path.c_str(), &raw), "lml_mesh_read_obj");
        return Mesh(MeshHandle(raw));
    }
    std::vector<double> positions() const {
        return fetch<double>([&](double *out, std::size_t capacity, std::size_t *needed) {
            return lml_mesh_positions(handle_.get(), out, capacity, needed);
        }, "lml_mesh_positions");
    }
    std::vector<std::uint32_t> triangles() const {
        return fetch<std::uint32_t>([&](std::uint32_t *out, std::size_t capacity, std::size_t *needed) {
            return lml_mesh_triangles(handle_.get(), out, capacity, needed);
        }, "lml_mesh_triangles");
    }
    const LmlMesh *get() const { return handle_.get(); }

private:
    explicit Mesh(MeshHandle handle) : handle_(std::move(handle)) {}
    MeshHandle handle_;
};

class Field {
public:
    Field(const Mesh &mesh, const std::vector<double> &initial, const LmlFieldParams &params) {
        LmlField *raw = nullptr;
        check(lml_field_new(mesh.get(), initial.data(), initial.size(), &params, &raw), "lml_field_new");
        handle_.reset(raw);
    }
    static LmlFieldParams pseudo_geodesic(double theta_degrees) {
        LmlFieldParams params;
        check(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, theta_degrees, &params), "lml_field_params_default");
        return params;
    }
    // Runs at most `max_iterations`; true once converged.
    bool step(std::uint32_t max_iterations, LmlReport &report) {
        return check(lml_field_step(handle_.get(), max_iterations, &report), "lml_field_step") == LML_STATUS_CONVERGED;
    }
    std::vector<double> values() const {
        return fetch<double>([&](double *out, std::size_t capacity, std::size_t *needed) {
            return lml_field_values(handle_.get(), out, capacity, needed);
        }, "lml_field_values");
    }
    std::vector<double> binormals() const {
        return fetch<double>([&](double *out, std::size_t capacity, std::size_t *needed) {
            return lml_field_binormals(handle_.get(), out, capacity, needed);
        }, "lml_field_binormals");
    }
    std::vector<std::uint8_t> save() const {
        return fetch<std::uint8_t>([&](std::uint8_t *out, std::size_t capacity, std::size_t *needed) {
            return lml_field_save(handle_.get(), out, capacity, needed);
        }, "lml_field_save");
    }
    static Field load(const std::vector<std::uint8_t> &bytes) {
        LmlField *raw = nullptr;
        check(lml_field_load(bytes.data(), bytes.size(), &raw), "lml_field_load");
        return Field(FieldHandle(raw));
    }
    const LmlField *get() const { return handle_.get(); }

private:
    friend class Search;
    explicit Field(FieldHandle handle) : handle_(std::move(handle)) {}
    FieldHandle handle_;
};

// The library's start search: several initial fields, a short solve from each, the best one
// continues as a Field. Step it until it returns false, then take the field.
class Search {
public:
    Search(const Mesh &mesh, const LmlFieldParams &params) {
        LmlSearch *raw = nullptr;
        check(lml_search_new(mesh.get(), &params, &raw), "lml_search_new");
        handle_.reset(raw);
    }
    // Probes the next candidate; true while candidates remain.
    bool step() { return check(lml_search_step(handle_.get()), "lml_search_step") == LML_STATUS_MORE; }
    std::size_t candidate_count() const {
        std::size_t count = 0;
        check(lml_search_candidate_count(handle_.get(), &count), "lml_search_candidate_count");
        return count;
    }
    LmlCandidate candidate(std::size_t index) const {
        LmlCandidate candidate;
        check(lml_search_candidate(handle_.get(), index, &candidate), "lml_search_candidate");
        return candidate;
    }
    // The candidate's description, e.g. "height along (1.000, 0.000, 0.000): score 1.19".
    std::string candidate_text(std::size_t index) const {
        std::vector<std::uint8_t> text = fetch<std::uint8_t>([&](std::uint8_t *out, std::size_t capacity, std::size_t *needed) {
            return lml_search_candidate_text(handle_.get(), index, out, capacity, needed);
        }, "lml_search_candidate_text");
        return std::string(text.begin(), text.end() - 1);  // without the NUL
    }
    std::size_t winner() const {
        std::size_t index = 0;
        check(lml_search_winner(handle_.get(), &index), "lml_search_winner");
        return index;
    }
    // The field of the best candidate, to be stepped to convergence; ends the search.
    Field take_field() {
        LmlField *raw = nullptr;
        check(lml_search_field(handle_.get(), &raw), "lml_search_field");
        return Field(FieldHandle(raw));
    }

private:
    SearchHandle handle_;
};

// Level curves of a field: polylines as points (x y z ...) cut by offsets (c + 1 entries).
class Curves {
public:
    // `count` uniform levels, resampled at `spacing` (0: not resampled).
    static Curves uniform(const Field &field, std::size_t count, double spacing) {
        LmlCurves *raw = nullptr;
        check(lml_curves_new_uniform(field.get(), count, spacing, &raw), "lml_curves_new_uniform");
        return Curves(CurvesHandle(raw));
    }
    std::vector<std::size_t> offsets() const {
        return fetch<std::size_t>([&](std::size_t *out, std::size_t capacity, std::size_t *needed) {
            return lml_curves_offsets(handle_.get(), out, capacity, needed);
        }, "lml_curves_offsets");
    }
    std::vector<double> points() const {
        return fetch<double>([&](double *out, std::size_t capacity, std::size_t *needed) {
            return lml_curves_points(handle_.get(), out, capacity, needed);
        }, "lml_curves_points");
    }
    const LmlCurves *get() const { return handle_.get(); }

private:
    explicit Curves(CurvesHandle handle) : handle_(std::move(handle)) {}
    CurvesHandle handle_;
};

// Rectifying strips: vertices (x y z ...), quads (4 indices each) cut per strip by quad offsets,
// and the Table 4 measures.
class Strips {
public:
    // Strips that miss theta (LML_STATUS_NO_ACCEPTABLE_FAMILY) are built all the same: see verdict().
    Strips(const Curves &curves, const LmlStripParams &params) {
        LmlStrips *raw = nullptr;
        LmlStatus status = check(lml_strips_new(curves.get(), &params, &raw), "lml_strips_new");
        handle_.reset(raw);
        if (status == LML_STATUS_NO_ACCEPTABLE_FAMILY) {
            verdict_message_ = lml_last_error_message();
        }
    }
    LmlVerdict verdict() const {
        LmlVerdict verdict;
        check(lml_strips_verdict(handle_.get(), &verdict), "lml_strips_verdict");
        return verdict;
    }
    // The library's message when the strips miss theta (names the strips, the worst point and
    // what to try), empty when they are acceptable.
    const std::string &verdict_message() const { return verdict_message_; }
    static LmlStripParams params(double theta_degrees, double width) {
        LmlStripParams params;
        check(lml_strip_params_default(theta_degrees, width, &params), "lml_strip_params_default");
        return params;
    }
    std::vector<double> vertices() const {
        return fetch<double>([&](double *out, std::size_t capacity, std::size_t *needed) {
            return lml_strips_vertices(handle_.get(), out, capacity, needed);
        }, "lml_strips_vertices");
    }
    std::vector<std::uint32_t> quads() const {
        return fetch<std::uint32_t>([&](std::uint32_t *out, std::size_t capacity, std::size_t *needed) {
            return lml_strips_quads(handle_.get(), out, capacity, needed);
        }, "lml_strips_quads");
    }
    std::vector<std::size_t> quad_offsets() const {
        return fetch<std::size_t>([&](std::size_t *out, std::size_t capacity, std::size_t *needed) {
            return lml_strips_quad_offsets(handle_.get(), out, capacity, needed);
        }, "lml_strips_quad_offsets");
    }
    std::vector<LmlStripMetrics> metrics() const {
        return fetch<LmlStripMetrics>([&](LmlStripMetrics *out, std::size_t capacity, std::size_t *needed) {
            return lml_strips_metrics(handle_.get(), out, capacity, needed);
        }, "lml_strips_metrics");
    }
    LmlPatternMetrics pattern_metrics() const {
        LmlPatternMetrics metrics;
        check(lml_strips_pattern_metrics(handle_.get(), &metrics), "lml_strips_pattern_metrics");
        return metrics;
    }

private:
    StripsHandle handle_;
    std::string verdict_message_;
};

}  // namespace lamella

#endif
