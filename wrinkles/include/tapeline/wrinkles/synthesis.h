// Wrinkle synthesis from data (W2): a database of (features → wrinkles) pairs learned from fine
// drapes of a fabric, and fine wrinkles added to a coarse drape of any garment of that fabric.
//
// Features, per coarse triangle (wrinkle_features): the compression 1 − s_min and the tension
// s_max − 1 of its principal stretches against the pattern, its shear angle, the draped surface's
// normal curvature along the crests and along the waves (strain.h), its distance to the body
// (clamped to 50 mm; 0 when no body is given, and a database says whether it used one), the
// wavelength the buckling law predicts there (classify.h; 0 where it predicts none) and the
// fabric's bending length C = (B/W)^{1/3} (fabric_lab.h).
//
// Targets, per coarse triangle of a training pair (train_wrinkle_database): the fine drape is
// embedded in the coarse one (embedding.h); in a window of the triangle's piece centred on its
// centroid, `window_length_mm` long along its compression axis and `window_width_mm` wide
// (PatternWindows, window.h), the fine drape's height profile, less its least-squares cubic (a
// fine drape refined from a coarse one sags and shifts by millimetres over regions larger than
// the window), has a dominant wavelength
// (pattern mm) and amplitude when its spectrum has one (peak share ≥ `min_peak_share`, not the
// longest of the wavelengths of at least `min_periods` periods in the window, amplitude ≥
// `min_amplitude_mm`: has_wave()); otherwise the target amplitude
// is 0 and there is no wavelength. A triangle whose window the piece's outline cuts to less than
// `min_window_cover` of its length gives no sample.
//
// Synthesis (synthesize_wrinkles): the features of every triangle of the new coarse drape,
// standardised by the database's means and deviations, find their k nearest training triangles
// (CGAL kd-tree, Euclidean); the predicted amplitude is their inverse-distance-weighted mean
// amplitude (zeros included: a region where half the look-alikes show no wave gets half the
// amplitude), the wavelength their amplitude-weighted mean over those with one. The per-triangle
// predictions are spread to the triangle corners of each piece (area-weighted; the compression
// axis as a doubled angle, which has no sign, weighted by amplitude; the wavenumber 1/λ weighted
// by amplitude). The coarse mesh is subdivided (subdivide.h) and its new vertices put on the
// smooth surface the coarse one stands for (embedding.h, smooth_coarse_point()); a fine vertex at
// barycentric b in coarse triangle T at pattern point p takes A, axis d and wavenumber k
// interpolated from T's corners and moves along the interpolated coarse normal by
// h = A·cos(2π·k·(p − c)·d), c the
// centroid of its piece's pattern: crests run across the compression axis, and cos has no sign
// so the axis needs none. Vertices on seams (in triangles of two pieces) stay where they are.
//
// Self-check: where the displacement brings a vertex closer to the body than it was and closer
// than `body_clearance_mm` (the body's signed distance grid), or makes a cloth edge cross a cloth
// triangle that it did not cross before (exact predicates, crossings.h), the displacement of the
// vertices involved and of their neighbours is halved, up to `fix_rounds` times, then set to 0.
// The report gives the counts before and after (exact inside test and crossings, quality.h), so a
// caller can see that synthesis introduced none.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/crossings.h>
#include <tapeline/garment/fabric_lab.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/garment/quality.h>
#include <tapeline/wrinkles/classify.h>
#include <tapeline/wrinkles/embedding.h>
#include <tapeline/wrinkles/strain.h>
#include <tapeline/wrinkles/subdivide.h>
#include <tapeline/wrinkles/window.h>

#include <CGAL/Epick_d.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Search_traits_d.h>
#include <CGAL/property_map.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace tapeline::wrinkles {

inline constexpr std::size_t kWrinkleFeatures = 8;

/// Names of the features, in their order (see the file comment).
inline const std::array<const char*, kWrinkleFeatures>& wrinkle_feature_names() {
    static const std::array<const char*, kWrinkleFeatures> names{"compression",
                                                                 "tension",
                                                                 "shear_deg",
                                                                 "crest_curvature_1_m",
                                                                 "wave_curvature_1_m",
                                                                 "body_distance_mm",
                                                                 "predicted_wavelength_mm",
                                                                 "bending_length_mm"};
    return names;
}

using FeatureVector = std::array<double, kWrinkleFeatures>;

/// The features of one coarse triangle and what synthesis needs besides.
struct TriangleFeatures {
    bool valid = false;  ///< false: degenerate pattern triangle
    FeatureVector f{};
    UV axis{1, 0};  ///< compression axis (waves' direction), unit, pattern coordinates
    WrinkleClass cls = WrinkleClass::none;
};

/// The body a garment is draped on (mm, the garment's frame), for features and checks.
struct BodySurface {
    const std::vector<Vec3>* points = nullptr;
    const std::vector<Tri>* triangles = nullptr;
    const garment::Collider* distance = nullptr;  ///< its signed distance
};

/// How the database measures its targets (see the file comment).
struct TrainOptions {
    double window_length_mm = 200;  ///< along the compression axis (> 0)
    double window_width_mm = 20;    ///< across it (> 0)
    double min_peak_share = 0.3;    ///< a dominant wavelength needs this share of the spectrum
    double min_amplitude_mm = 0.1;  ///< and this amplitude
    /// Wavelengths of at least this many periods in the window are looked at (>= 2), and a peak
    /// at the longest of them is no wave: the detrended profile of a smooth, garment-scale
    /// difference between two drapes (a low-order polynomial over the window) has a spectrum that
    /// falls with frequency, so its largest magnitude sits at whatever limit is set.
    double min_periods = 4;
    /// A window that covers less than this share of its length (cut by the piece's outline) is
    /// no sample: its missing wave would be the outline's, not the fabric's.
    double min_window_cover = 0.75;
    ClassifyOptions classify;  ///< for the predicted wavelength feature and the classes
};

/// A training database for one fabric.
struct WrinkleDatabase {
    std::string fabric;  ///< the fabric's name
    double bending_length_mm = 0;
    bool uses_body = false;  ///< the body distance feature was measured (not 0)
    TrainOptions options;
    std::vector<FeatureVector> features;  ///< per sample
    std::vector<double> amplitude_mm;     ///< per sample, 0: no dominant wavelength
    std::vector<double> wavelength_mm;    ///< per sample, pattern mm; NaN: none
    std::vector<std::uint8_t> cls;        ///< per sample, WrinkleClass
    FeatureVector mean{}, scale{};        ///< standardisation (scale > 0)
    std::vector<std::string> sources;     ///< one line per training pair
};

namespace internal {

inline double clamp_distance(double d) {
    return std::clamp(d, 0.0, 50.0);
}

inline void check_body(const BodySurface& b, const char* who) {
    if ((b.points == nullptr) != (b.triangles == nullptr)) {
        throw InvalidInput(std::string(who) + ": a body needs both its points and its triangles");
    }
}

}  // namespace internal

/// The features of every triangle of `g` (see the file comment). `body.distance` may be null
/// (the distance feature is then 0).
/// \throws InvalidInput as classify_wrinkles().
inline std::vector<TriangleFeatures> wrinkle_features(const garment::GarmentMesh& g,
                                                      const garment::FabricParams& fabric,
                                                      const garment::Collider* body,
                                                      const ClassifyOptions& co = {}) {
    const WrinkleField field = classify_wrinkles(g, fabric, co);
    const std::vector<Vec3> normals = draw::vertex_normals(g.positions, g.triangles);
    const double c_mm = garment::bending_length_mm(fabric.bending_un_m, fabric.density_g_m2);
    std::vector<TriangleFeatures> out(g.triangles.size());
    for (std::size_t t = 0; t < g.triangles.size(); ++t) {
        const TriangleWrinkles& w = field.triangles[t];
        TriangleFeatures& tf = out[t];
        tf.cls = w.cls;
        if (!w.strain.valid) {
            continue;
        }
        tf.valid = true;
        const TriangleStrain& s = w.strain;
        const TriangleCurvature k = triangle_curvature(g.positions, g.triangles[t], normals);
        double dist = 0;
        if (body != nullptr) {
            const Tri& f = g.triangles[t];
            const Vec3 c = vec3::scale(
                vec3::add(vec3::add(g.positions[f[0]], g.positions[f[1]]), g.positions[f[2]]),
                1.0 / 3);
            dist = internal::clamp_distance(body->signed_distance(c, nullptr));
        }
        tf.f = {1 - s.s_min,
                s.s_max - 1,
                std::abs(s.shear_rad) * 180 / M_PI,
                std::abs(k.along(s.dir_max)) * 1e3,
                std::abs(k.along(s.dir_min)) * 1e3,
                dist,
                std::isfinite(w.wavelength_mm) ? w.wavelength_mm : 0.0,
                c_mm};
        tf.axis = s.rest_min;
    }
    return out;
}

/// Whether a window's profile shows a wave by the rules of `o` (see the file comment).
inline bool has_wave(const WindowProfile& p, const TrainOptions& o) {
    return p.resolved && p.spectrum.wavelength > 0 && !p.spectrum.at_record_limit &&
           p.spectrum.peak_share >= o.min_peak_share && p.spectrum.amplitude >= o.min_amplitude_mm;
}

/// One training pair: a coarse drape and a fine drape of the same garment, fabric and body.
struct TrainingPair {
    const garment::GarmentMesh* coarse = nullptr;
    const garment::GarmentMesh* fine = nullptr;
    const garment::Collider* body = nullptr;  ///< may be null (no distance feature)
    std::string source;                       ///< a line naming where it came from
};

/// Adds the samples of `pair` to `db` (see the file comment): every coarse triangle with a
/// valid pattern triangle is one sample. Returns the number added. The first pair fixes whether
/// the database uses the body; a later pair must agree.
/// \throws InvalidInput as embed_fine_in_coarse() and wrinkle_features(), for a pair with a
///         missing mesh, a body given to one pair and not another, or bad options.
inline std::size_t add_training_pair(WrinkleDatabase& db, const TrainingPair& pair,
                                     const garment::FabricParams& fabric) {
    const TrainOptions& o = db.options;
    if (!(o.window_length_mm > 0 && o.window_width_mm > 0 && std::isfinite(o.window_length_mm) &&
          std::isfinite(o.window_width_mm))) {
        throw InvalidInput(
            "wrinkle training: the window's length and width must be finite and > 0");
    }
    if (!(o.min_periods >= 2 && std::isfinite(o.min_periods))) {
        throw InvalidInput("wrinkle training: min_periods must be finite and >= 2, got " +
                           std::to_string(o.min_periods));
    }
    if (pair.coarse == nullptr || pair.fine == nullptr) {
        throw InvalidInput("wrinkle training: pair '" + pair.source + "' misses a mesh");
    }
    if (db.features.empty() && db.sources.empty()) {
        db.fabric = fabric.name;
        db.bending_length_mm = garment::bending_length_mm(fabric.bending_un_m, fabric.density_g_m2);
        db.uses_body = pair.body != nullptr;
    } else if (db.uses_body != (pair.body != nullptr)) {
        throw InvalidInput("wrinkle training: pair '" + pair.source + "' " +
                           (db.uses_body ? "has no body, the earlier pairs had one"
                                         : "has a body, the earlier pairs had none"));
    } else if (db.fabric != fabric.name) {
        throw InvalidInput("wrinkle training: pair '" + pair.source + "' is of fabric '" +
                           fabric.name + "', the database of '" + db.fabric + "'");
    }
    const auto feats = wrinkle_features(*pair.coarse, fabric, pair.body, o.classify);
    const Embedding e = embed_fine_in_coarse(*pair.coarse, *pair.fine);
    std::vector<double> h(pair.fine->positions.size(), 0.0);
    for (std::size_t v = 0; v < h.size(); ++v) {
        h[v] = e.vertices[v].height_mm;
    }
    const PatternWindows windows(*pair.fine, std::move(h));
    std::size_t added = 0;
    for (std::size_t t = 0; t < feats.size(); ++t) {
        if (!feats[t].valid) {
            continue;
        }
        const UV centre = pattern_centroid(pair.coarse->uv[t]);
        const WindowProfile p =
            windows.profile(pair.coarse->triangle_piece[t], centre, feats[t].axis,
                            0.5 * o.window_length_mm, 0.5 * o.window_width_mm, o.min_periods, 3);
        double a = 0, lam = std::numeric_limits<double>::quiet_NaN();
        if (has_wave(p, o)) {
            a = p.spectrum.amplitude;
            lam = p.spectrum.wavelength;
        }
        if (!p.resolved || p.span_mm < o.min_window_cover * o.window_length_mm) {
            continue;  // cut by the outline, or too few fine vertices around it: no target
        }
        db.features.push_back(feats[t].f);
        db.amplitude_mm.push_back(a);
        db.wavelength_mm.push_back(lam);
        db.cls.push_back(std::uint8_t(feats[t].cls));
        ++added;
    }
    db.sources.push_back(pair.source);
    return added;
}

/// Sets the database's standardisation from its samples (mean and standard deviation per
/// feature; a constant feature gets scale 1). Call after the last add_training_pair().
/// \throws InvalidInput when the database has no samples.
inline void finish_database(WrinkleDatabase& db) {
    if (db.features.empty()) {
        throw InvalidInput("wrinkle training: the database has no samples");
    }
    const double n = double(db.features.size());
    for (std::size_t j = 0; j < kWrinkleFeatures; ++j) {
        double s = 0, s2 = 0;
        for (const FeatureVector& f : db.features) {
            s += f[j];
        }
        const double m = s / n;
        for (const FeatureVector& f : db.features) {
            s2 += (f[j] - m) * (f[j] - m);
        }
        const double sd = std::sqrt(s2 / n);
        db.mean[j] = m;
        db.scale[j] = sd > 1e-12 * std::max(1.0, std::abs(m)) ? sd : 1.0;
    }
}

/// The database as JSON (format "tapeline-wrinkle-db", version 1).
inline nlohmann::ordered_json wrinkle_database_json(const WrinkleDatabase& db) {
    nlohmann::ordered_json j;
    j["format"] = "tapeline-wrinkle-db";
    j["version"] = 1;
    j["fabric"] = db.fabric;
    j["bending_length_mm"] = db.bending_length_mm;
    j["uses_body"] = db.uses_body;
    j["window_length_mm"] = db.options.window_length_mm;
    j["window_width_mm"] = db.options.window_width_mm;
    j["min_peak_share"] = db.options.min_peak_share;
    j["min_amplitude_mm"] = db.options.min_amplitude_mm;
    j["min_periods"] = db.options.min_periods;
    j["min_window_cover"] = db.options.min_window_cover;
    j["compression_threshold"] = db.options.classify.compression_threshold;
    j["tension_threshold"] = db.options.classify.tension_threshold;
    j["shear_threshold_deg"] = db.options.classify.shear_threshold_deg;
    j["tension_length_mm"] = db.options.classify.tension_length_mm;
    j["features"] = nlohmann::ordered_json::array();
    for (const char* n : wrinkle_feature_names()) {
        j["features"].push_back(n);
    }
    j["mean"] = db.mean;
    j["scale"] = db.scale;
    j["sources"] = db.sources;
    auto& s = j["samples"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < db.features.size(); ++i) {
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (double x : db.features[i]) {
            row.push_back(x);
        }
        row.push_back(db.amplitude_mm[i]);
        row.push_back(std::isfinite(db.wavelength_mm[i])
                          ? nlohmann::ordered_json(db.wavelength_mm[i])
                          : nlohmann::ordered_json(nullptr));
        row.push_back(int(db.cls[i]));
        s.push_back(std::move(row));
    }
    return j;
}

/// Reads a database written by wrinkle_database_json().
/// \throws InvalidInput naming `where` and the field or sample: another format or version,
///         other features, a missing or mistyped field, a value that is not finite (a wavelength
///         may be null), a negative amplitude, a scale that is not > 0, no samples.
inline WrinkleDatabase wrinkle_database_from_json(const nlohmann::json& j,
                                                  const std::string& where) {
    const auto fail = [&](const std::string& what) { throw InvalidInput(where + ": " + what); };
    if (!j.is_object() || j.value("format", std::string()) != "tapeline-wrinkle-db") {
        fail("not a wrinkle database (no \"format\": \"tapeline-wrinkle-db\")");
    }
    if (!j.contains("version") || !j["version"].is_number_integer() || j["version"] != 1) {
        fail("unsupported version (this reads version 1)");
    }
    const auto num = [&](const char* key) {
        if (!j.contains(key) || !j[key].is_number() || !std::isfinite(j[key].get<double>())) {
            fail(std::string("\"") + key + "\" must be a finite number");
        }
        return j[key].get<double>();
    };
    WrinkleDatabase db;
    if (!j.contains("fabric") || !j["fabric"].is_string() ||
        j["fabric"].get<std::string>().empty()) {
        fail("\"fabric\" must be a non-empty string");
    }
    db.fabric = j["fabric"].get<std::string>();
    db.bending_length_mm = num("bending_length_mm");
    if (!j.contains("uses_body") || !j["uses_body"].is_boolean()) {
        fail("\"uses_body\" must be true or false");
    }
    db.uses_body = j["uses_body"].get<bool>();
    db.options.window_length_mm = num("window_length_mm");
    db.options.window_width_mm = num("window_width_mm");
    db.options.min_peak_share = num("min_peak_share");
    db.options.min_amplitude_mm = num("min_amplitude_mm");
    db.options.min_periods = num("min_periods");
    db.options.min_window_cover = num("min_window_cover");
    db.options.classify.compression_threshold = num("compression_threshold");
    db.options.classify.tension_threshold = num("tension_threshold");
    db.options.classify.shear_threshold_deg = num("shear_threshold_deg");
    db.options.classify.tension_length_mm = num("tension_length_mm");
    if (!j.contains("features") || !j["features"].is_array() ||
        j["features"].size() != kWrinkleFeatures) {
        fail("\"features\" must list the " + std::to_string(kWrinkleFeatures) + " features");
    }
    for (std::size_t k = 0; k < kWrinkleFeatures; ++k) {
        if (!j["features"][k].is_string() ||
            j["features"][k].get<std::string>() != wrinkle_feature_names()[k]) {
            fail("feature " + std::to_string(k) + " must be \"" + wrinkle_feature_names()[k] +
                 "\"");
        }
    }
    for (const char* key : {"mean", "scale"}) {
        if (!j.contains(key) || !j[key].is_array() || j[key].size() != kWrinkleFeatures) {
            fail(std::string("\"") + key + "\" must hold " + std::to_string(kWrinkleFeatures) +
                 " numbers");
        }
        for (std::size_t k = 0; k < kWrinkleFeatures; ++k) {
            const auto& x = j[key][k];
            if (!x.is_number() || !std::isfinite(x.get<double>()) ||
                (std::string(key) == "scale" && !(x.get<double>() > 0))) {
                fail(std::string("\"") + key + "\"[" + std::to_string(k) + "] must be a finite" +
                     (std::string(key) == "scale" ? " number > 0" : " number"));
            }
            (std::string(key) == "mean" ? db.mean : db.scale)[k] = x.get<double>();
        }
    }
    if (j.contains("sources") && j["sources"].is_array()) {
        for (const auto& s : j["sources"]) {
            db.sources.push_back(s.is_string() ? s.get<std::string>() : s.dump());
        }
    }
    if (!j.contains("samples") || !j["samples"].is_array() || j["samples"].empty()) {
        fail("\"samples\" must be a non-empty array");
    }
    const auto& samples = j["samples"];
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const auto& r = samples[i];
        const std::string at = "sample " + std::to_string(i);
        if (!r.is_array() || r.size() != kWrinkleFeatures + 3) {
            fail(at + " must hold " + std::to_string(kWrinkleFeatures + 3) + " values");
        }
        FeatureVector f{};
        for (std::size_t k = 0; k < kWrinkleFeatures; ++k) {
            if (!r[k].is_number() || !std::isfinite(r[k].get<double>())) {
                fail(at + ": feature " + wrinkle_feature_names()[k] + " is not a finite number");
            }
            f[k] = r[k].get<double>();
        }
        const auto& a = r[kWrinkleFeatures];
        if (!a.is_number() || !(a.get<double>() >= 0) || !std::isfinite(a.get<double>())) {
            fail(at + ": the amplitude must be a finite number >= 0");
        }
        const auto& l = r[kWrinkleFeatures + 1];
        double lam = std::numeric_limits<double>::quiet_NaN();
        if (!l.is_null()) {
            if (!l.is_number() || !(l.get<double>() > 0) || !std::isfinite(l.get<double>())) {
                fail(at + ": the wavelength must be null or a finite number > 0");
            }
            lam = l.get<double>();
        }
        if (a.get<double>() > 0 && !std::isfinite(lam)) {
            fail(at + ": an amplitude above 0 needs a wavelength");
        }
        const auto& c = r[kWrinkleFeatures + 2];
        if (!c.is_number_integer() || c.get<int>() < 0 || c.get<int>() >= int(kWrinkleClasses)) {
            fail(at + ": the class must be an integer 0-3");
        }
        db.features.push_back(f);
        db.amplitude_mm.push_back(a.get<double>());
        db.wavelength_mm.push_back(lam);
        db.cls.push_back(std::uint8_t(c.get<int>()));
    }
    return db;
}

/// How wrinkles are synthesised and checked (see the file comment).
struct SynthesisOptions {
    int levels = 2;                  ///< subdivision levels (1–4)
    std::size_t neighbours = 8;      ///< k of the nearest neighbours (>= 1)
    double body_clearance_mm = 1.0;  ///< the displacement may not bring cloth closer than this
    int fix_rounds = 4;              ///< halvings before a displacement is dropped (>= 0)
    bool check = true;               ///< exact before/after figures (garment_quality) with a body
};

/// What synthesis predicted for one coarse triangle.
struct TrianglePrediction {
    double amplitude_mm = 0;
    double wavelength_mm = std::numeric_limits<double>::quiet_NaN();  ///< pattern mm
    UV axis{1, 0};
    WrinkleClass cls = WrinkleClass::none;
};

/// Figures of one synthesis.
struct SynthesisReport {
    std::size_t coarse_triangles = 0, fine_vertices = 0, fine_triangles = 0;
    std::size_t database_samples = 0;
    std::size_t displaced = 0;  ///< fine vertices moved by more than 0.01 mm
    double rms_height_mm = 0, max_height_mm = 0;
    /// Per class of coarse triangle: median predicted amplitude and wavelength (pattern mm) over
    /// its triangles with an amplitude above 0 (NaN: none), and how many have one.
    ///@{
    std::array<double, kWrinkleClasses> median_amplitude_mm{}, median_wavelength_mm{};
    std::array<std::size_t, kWrinkleClasses> with_wrinkles{};
    ///@}
    /// Self-check (see the file comment): vertices whose displacement was reduced, rounds taken,
    /// and the crossings and close-to-body vertices the last round still found (0: none new).
    std::size_t damped_vertices = 0;
    int fix_rounds_used = 0;
    std::size_t new_self_crossings_left = 0, new_body_contacts_left = 0;
    bool body_checked = false;
    /// garment_quality() of the subdivided coarse drape and of the result (with a body and
    /// SynthesisOptions::check).
    ///@{
    garment::QualityFigures quality_before, quality_after;
    ///@}
    double synthesis_seconds = 0;  ///< features, neighbours, subdivision, displacement
    double fix_seconds = 0;        ///< the self-check's rounds
    double check_seconds = 0;      ///< the exact figures
};

/// A coarse drape with synthesised wrinkles.
struct Synthesis {
    garment::GarmentMesh fine;
    Subdivision subdivision;  ///< the flat subdivided mesh and where its vertices came from
    /// The subdivided mesh on the smooth coarse surface (embedding.h): `fine` without wrinkles.
    garment::GarmentMesh base;
    std::vector<double> height_mm;              ///< per fine vertex, along the coarse normal
    std::vector<Vec3> normal;                   ///< per fine vertex, unit
    std::vector<TrianglePrediction> triangles;  ///< per coarse triangle
    /// Per coarse triangle corner (3 per triangle): amplitude, doubled-angle axis (weighted by
    /// amplitude) and wavenumber 1/λ, as interpolated to fine vertices.
    std::vector<std::array<double, 4>> corner;
    std::vector<UV> piece_centre;       ///< pattern centroid of each piece
    std::vector<std::uint8_t> on_seam;  ///< per coarse vertex
    SynthesisReport report;

    /// The synthesised height at a pattern point `p` of piece `piece` lying at barycentric `b`
    /// in coarse triangle `t` (0 on a seam vertex).
    double height_at(std::uint32_t t, const std::array<double, 3>& b, const UV& p,
                     std::uint32_t piece) const {
        double a = 0, c2 = 0, s2 = 0, k = 0;
        for (int i = 0; i < 3; ++i) {
            const auto& c = corner[3 * t + std::size_t(i)];
            a += b[std::size_t(i)] * c[0];
            c2 += b[std::size_t(i)] * c[1];
            s2 += b[std::size_t(i)] * c[2];
            k += b[std::size_t(i)] * c[3];
        }
        const double l = std::hypot(c2, s2);
        if (!(a > 0) || !(l > 0) || !(k > 0)) {
            return 0;
        }
        const double th = 0.5 * std::atan2(s2, c2);
        const UV d{std::cos(th), std::sin(th)};
        const UV& c = piece_centre[piece];
        const double s = (p[0] - c[0]) * d[0] + (p[1] - c[1]) * d[1];
        return a * std::cos(2 * M_PI * k * s);
    }
};

namespace internal {

inline void check_synthesis_options(const SynthesisOptions& o) {
    if (o.levels < 1 || o.levels > 4) {
        throw InvalidInput("wrinkle synthesis: levels must be in [1, 4], got " +
                           std::to_string(o.levels));
    }
    if (o.neighbours < 1) {
        throw InvalidInput("wrinkle synthesis: neighbours must be >= 1");
    }
    if (!(o.body_clearance_mm >= 0 && std::isfinite(o.body_clearance_mm))) {
        throw InvalidInput("wrinkle synthesis: body_clearance_mm must be finite and >= 0, got " +
                           std::to_string(o.body_clearance_mm));
    }
    if (o.fix_rounds < 0 || o.fix_rounds > 20) {
        throw InvalidInput("wrinkle synthesis: fix_rounds must be in [0, 20], got " +
                           std::to_string(o.fix_rounds));
    }
}

/// k nearest samples of a database in its standardised feature space.
class FeatureIndex {
public:
    explicit FeatureIndex(const WrinkleDatabase& db) : db_(db) {
        std::vector<Entry> entries;
        entries.reserve(db.features.size());
        for (std::size_t i = 0; i < db.features.size(); ++i) {
            entries.emplace_back(point(db.features[i]), i);
        }
        tree_.insert(entries.begin(), entries.end());
        tree_.build();
    }
    /// (sample, distance) of the k nearest, nearest first.
    std::vector<std::pair<std::size_t, double>> nearest(const FeatureVector& f,
                                                        std::size_t k) const {
        Search search(tree_, point(f), static_cast<unsigned int>(k), 0, true,
                      Distance(CGAL::Nth_of_tuple_property_map<0, Entry>()));
        std::vector<std::pair<std::size_t, double>> out;
        for (const auto& hit : search) {
            out.emplace_back(std::get<1>(hit.first), std::sqrt(hit.second));
        }
        return out;
    }

private:
    using Kernel = CGAL::Epick_d<CGAL::Dimension_tag<kWrinkleFeatures>>;
    using Point = Kernel::Point_d;
    using Entry = std::tuple<Point, std::size_t>;
    using Base = CGAL::Search_traits_d<Kernel, CGAL::Dimension_tag<kWrinkleFeatures>>;
    using Traits =
        CGAL::Search_traits_adapter<Entry, CGAL::Nth_of_tuple_property_map<0, Entry>, Base>;
    using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
    using Tree = Search::Tree;
    using Distance = Search::Distance;

    Point point(const FeatureVector& f) const {
        std::array<double, kWrinkleFeatures> z{};
        for (std::size_t j = 0; j < kWrinkleFeatures; ++j) {
            z[j] = (f[j] - db_.mean[j]) / db_.scale[j];
        }
        return Point(z.begin(), z.end());
    }

    const WrinkleDatabase& db_;
    Tree tree_;
};

}  // namespace internal

/// Adds wrinkles from `db` to the coarse drape `coarse` of `fabric` (see the file comment).
/// `body` (may be empty) gives the distance feature and the self-check.
///
/// \throws InvalidInput: bad options; a database of another fabric, without samples or with
///         other options; a database trained with the body distance and no body given; anything
///         wrinkle_features() or subdivide() refuse.
inline Synthesis synthesize_wrinkles(const garment::GarmentMesh& coarse, const WrinkleDatabase& db,
                                     const garment::FabricParams& fabric, const BodySurface& body,
                                     const SynthesisOptions& o = {}) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    internal::check_synthesis_options(o);
    internal::check_body(body, "wrinkle synthesis");
    if (db.features.empty() || db.amplitude_mm.size() != db.features.size() ||
        db.wavelength_mm.size() != db.features.size()) {
        throw InvalidInput("wrinkle synthesis: the database has no samples");
    }
    if (db.fabric != fabric.name) {
        throw InvalidInput("wrinkle synthesis: the database was trained on fabric '" + db.fabric +
                           "', the garment is of '" + fabric.name +
                           "' (train a database for that fabric)");
    }
    if (db.uses_body && body.distance == nullptr) {
        throw InvalidInput(
            "wrinkle synthesis: the database uses the distance to the body; give the body");
    }
    Synthesis out;
    SynthesisReport& r = out.report;
    const auto feats = wrinkle_features(coarse, fabric, db.uses_body ? body.distance : nullptr,
                                        db.options.classify);
    const internal::FeatureIndex index(db);
    const std::size_t k = std::min(o.neighbours, db.features.size());
    out.triangles.resize(coarse.triangles.size());
    std::array<std::vector<double>, kWrinkleClasses> amps, lams;
    for (std::size_t t = 0; t < feats.size(); ++t) {
        TrianglePrediction& p = out.triangles[t];
        p.cls = feats[t].cls;
        p.axis = feats[t].axis;
        if (!feats[t].valid) {
            continue;
        }
        double wsum = 0, asum = 0, lw = 0, lsum = 0;
        for (const auto& [i, d] : index.nearest(feats[t].f, k)) {
            const double w = 1 / (d + 1e-3);
            wsum += w;
            asum += w * db.amplitude_mm[i];
            if (db.amplitude_mm[i] > 0 && std::isfinite(db.wavelength_mm[i])) {
                lw += w * db.amplitude_mm[i];
                lsum += w * db.amplitude_mm[i] * db.wavelength_mm[i];
            }
        }
        if (lw > 0) {
            p.amplitude_mm = asum / wsum;
            p.wavelength_mm = lsum / lw;
            amps[std::size_t(p.cls)].push_back(p.amplitude_mm);
            lams[std::size_t(p.cls)].push_back(p.wavelength_mm);
        }
    }
    for (std::size_t c = 0; c < kWrinkleClasses; ++c) {
        r.median_amplitude_mm[c] = internal::median(amps[c]);
        r.median_wavelength_mm[c] = internal::median(lams[c]);
        r.with_wrinkles[c] = amps[c].size();
    }
    // Corner fields: accumulate over the triangles of one piece around a vertex; the pieces'
    // pattern centroids on the way.
    const std::size_t nt = coarse.triangles.size();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<double, 5>> acc;  // (v, piece)
    std::vector<double> piece_area;
    for (std::size_t t = 0; t < nt; ++t) {
        const double area = pattern_area(coarse.uv[t]);
        const UV centroid = pattern_centroid(coarse.uv[t]);
        const TrianglePrediction& p = out.triangles[t];
        const std::uint32_t piece = coarse.triangle_piece[t];
        if (piece >= piece_area.size()) {
            piece_area.resize(piece + 1, 0.0);
            out.piece_centre.resize(piece + 1, {0, 0});
        }
        out.piece_centre[piece][0] += area * centroid[0];
        out.piece_centre[piece][1] += area * centroid[1];
        piece_area[piece] += area;
        const double th2 = 2 * std::atan2(p.axis[1], p.axis[0]);
        const double a = p.amplitude_mm;
        for (std::uint32_t v : coarse.triangles[t]) {
            auto& c = acc[{v, piece}];
            c[0] += area * a;
            c[1] += area * a * std::cos(th2);
            c[2] += area * a * std::sin(th2);
            c[3] += a > 0 ? area * a / p.wavelength_mm : 0;
            c[4] += area;
        }
    }
    for (std::size_t i = 0; i < piece_area.size(); ++i) {
        if (piece_area[i] > 0) {
            out.piece_centre[i] = {out.piece_centre[i][0] / piece_area[i],
                                   out.piece_centre[i][1] / piece_area[i]};
        }
    }
    out.on_seam = internal::vertex_pattern(coarse).seam;
    out.corner.resize(3 * nt);
    for (std::size_t t = 0; t < nt; ++t) {
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t v = coarse.triangles[t][std::size_t(i)];
            const auto& c = acc[{v, coarse.triangle_piece[t]}];
            auto& cf = out.corner[3 * t + std::size_t(i)];
            const double amp = c[4] > 0 ? c[0] / c[4] : 0;
            cf = {out.on_seam[v] ? 0.0 : amp, c[4] > 0 ? c[1] / c[4] : 0.0,
                  c[4] > 0 ? c[2] / c[4] : 0.0, c[0] > 0 ? c[3] / c[0] : 0.0};
        }
    }
    // Subdivide, then displace.
    out.subdivision = subdivide(coarse, o.levels);
    const Subdivision& sd = out.subdivision;
    const std::vector<Vec3> cn = draw::vertex_normals(coarse.positions, coarse.triangles);
    // The wrinkles sit on the smooth surface the coarse drape stands for (embedding.h), which is
    // also what the database's heights were measured from.
    out.base = sd.mesh;
    for (std::size_t v = 0; v < out.base.positions.size(); ++v) {
        const auto& b = sd.barycentric[v];
        if (b[0] + b[1] + b[2] > 0.5) {
            out.base.positions[v] = internal::smooth_coarse_point(
                coarse.positions, coarse.triangles[sd.coarse_triangle[v]], cn, b);
        }
    }
    const garment::GarmentMesh& base = out.base;
    const std::size_t nv = base.positions.size();
    out.height_mm.assign(nv, 0.0);
    out.normal.assign(nv, Vec3{0, 0, 0});
    const internal::VertexPattern vp = internal::vertex_pattern(base);
    for (std::size_t v = 0; v < nv; ++v) {
        const std::uint32_t t = sd.coarse_triangle[v];
        const auto& b = sd.barycentric[v];
        out.normal[v] = internal::smooth_coarse_normal(coarse.triangles[t], cn, b);
        if (!vp.used[v] || vp.seam[v]) {
            continue;
        }
        // The vertex's own piece is the coarse triangle's (true for midpoint subdivision except
        // on seams, left out above).
        out.height_mm[v] = out.height_at(t, b, vp.uv[v], vp.piece[v]);
    }
    out.fine = base;
    for (std::size_t v = 0; v < nv; ++v) {
        out.fine.positions[v] =
            vec3::add(base.positions[v], vec3::scale(out.normal[v], out.height_mm[v]));
    }
    r.synthesis_seconds = std::chrono::duration<double>(Clock::now() - t0).count();

    // Self-check and repair.
    const auto t1 = Clock::now();
    std::vector<std::vector<std::uint32_t>> ring(nv);
    for (const Tri& t : base.triangles) {
        for (int i = 0; i < 3; ++i) {
            ring[t[std::size_t(i)]].push_back(t[std::size_t((i + 1) % 3)]);
            ring[t[std::size_t(i)]].push_back(t[std::size_t((i + 2) % 3)]);
        }
    }
    std::vector<double> d0;
    if (body.distance != nullptr) {
        d0.resize(nv);
        for (std::size_t v = 0; v < nv; ++v) {
            d0[v] = body.distance->signed_distance(base.positions[v], nullptr);
        }
    }
    using Crossing = std::tuple<std::uint32_t, std::uint32_t, std::size_t>;
    std::set<Crossing> before;
    garment::internal::for_each_edge_triangle_crossing(
        base.positions, base.triangles, [&](std::uint32_t a, std::uint32_t b, std::size_t t) {
            before.insert({a, b, t});
        });
    std::vector<double> factor(nv, 1.0);
    std::vector<std::uint8_t> damped(nv, 0);
    for (int round = 0; round <= o.fix_rounds; ++round) {
        std::vector<std::uint8_t> bad(nv, 0);
        std::size_t self_new = 0, body_new = 0;
        garment::internal::for_each_edge_triangle_crossing(
            out.fine.positions, base.triangles,
            [&](std::uint32_t a, std::uint32_t b, std::size_t t) {
                if (before.count({a, b, t}) == 0) {
                    ++self_new;
                    bad[a] = bad[b] = 1;
                    for (std::uint32_t c : base.triangles[t]) {
                        bad[c] = 1;
                    }
                }
            });
        if (body.distance != nullptr) {
            for (std::size_t v = 0; v < nv; ++v) {
                if (out.height_mm[v] == 0) {
                    continue;
                }
                const double d = body.distance->signed_distance(out.fine.positions[v], nullptr);
                if (d < d0[v] && d < o.body_clearance_mm) {
                    ++body_new;
                    bad[v] = 1;
                }
            }
        }
        r.new_self_crossings_left = self_new;
        r.new_body_contacts_left = body_new;
        if (self_new == 0 && body_new == 0) {
            break;
        }
        if (round == o.fix_rounds) {
            break;
        }
        r.fix_rounds_used = round + 1;
        std::vector<std::uint8_t> hit = bad;
        for (std::size_t v = 0; v < nv; ++v) {
            if (bad[v]) {
                for (std::uint32_t w : ring[v]) {
                    hit[w] = 1;
                }
            }
        }
        const bool last = round + 1 == o.fix_rounds;
        for (std::size_t v = 0; v < nv; ++v) {
            if (hit[v] && out.height_mm[v] != 0) {
                factor[v] = last ? 0.0 : 0.5 * factor[v];
                damped[v] = 1;
                const double h = out.height_mm[v] * factor[v];
                out.fine.positions[v] = vec3::add(base.positions[v], vec3::scale(out.normal[v], h));
            }
        }
    }
    for (std::size_t v = 0; v < nv; ++v) {
        out.height_mm[v] *= factor[v];
    }
    r.damped_vertices = std::size_t(std::count(damped.begin(), damped.end(), 1));
    r.body_checked = body.distance != nullptr;
    r.fix_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
    double s2 = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        s2 += out.height_mm[v] * out.height_mm[v];
        r.max_height_mm = std::max(r.max_height_mm, std::abs(out.height_mm[v]));
        r.displaced += std::abs(out.height_mm[v]) > 0.01 ? 1 : 0;
    }
    r.rms_height_mm = nv ? std::sqrt(s2 / double(nv)) : 0;
    r.coarse_triangles = nt;
    r.fine_vertices = nv;
    r.fine_triangles = base.triangles.size();
    r.database_samples = db.features.size();
    if (o.check && body.points != nullptr) {
        const auto t2 = Clock::now();
        r.quality_before = garment::garment_quality(*body.points, *body.triangles, base, 0, 0);
        r.quality_after = garment::garment_quality(*body.points, *body.triangles, out.fine, 0, 0);
        r.check_seconds = std::chrono::duration<double>(Clock::now() - t2).count();
    }
    return out;
}

/// A synthesis against a fine simulation of the same garment (held out from the database).
struct SynthesisCheckRow {
    std::size_t windows = 0;    ///< coarse triangles of the class with a resolved window
    std::size_t simulated = 0;  ///< of them, windows where the simulation has a dominant wave
    std::size_t both = 0;       ///< and the synthesis too
    double median_wavelength_error_percent = std::numeric_limits<double>::quiet_NaN();
    double median_amplitude_error_percent = std::numeric_limits<double>::quiet_NaN();
    double pearson_r = std::numeric_limits<double>::quiet_NaN();  ///< heights, over its vertices
    std::size_t vertices = 0;  ///< simulation vertices in the class's triangles
};

struct SynthesisCheck {
    std::array<SynthesisCheckRow, kWrinkleClasses> per_class;
    SynthesisCheckRow all;  ///< over the compressed classes (tension, shear, compression)
    double simulated_rms_height_mm = 0, synthesised_rms_height_mm = 0;
};

/// Compares `s` (synthesised on `coarse`) with `simulated`, a fine drape of the same garment:
/// both height fields over the coarse drape, per wrinkle class of the coarse triangles: the
/// dominant wavelength and amplitude in the database's windows (errors of the synthesis against
/// the simulation where the simulation has a dominant wave; a synthesis without one there counts
/// an amplitude error of 100 %), and the Pearson correlation of the two heights at the simulated
/// vertices.
/// \throws InvalidInput as embed_fine_in_coarse().
inline SynthesisCheck check_synthesis(const garment::GarmentMesh& coarse, const Synthesis& s,
                                      const WrinkleDatabase& db,
                                      const garment::GarmentMesh& simulated) {
    const Embedding e = embed_fine_in_coarse(coarse, simulated);
    std::vector<double> hs(simulated.positions.size(), 0.0), hy(simulated.positions.size(), 0.0);
    const internal::VertexPattern vp = internal::vertex_pattern(simulated);
    SynthesisCheck out;
    double ss = 0, sy = 0;
    std::size_t n = 0;
    // Pearson sums per class: n, Σx, Σy, Σxx, Σyy, Σxy.
    std::array<std::array<double, 6>, kWrinkleClasses + 1> ps{};
    for (std::size_t v = 0; v < hs.size(); ++v) {
        if (!vp.used[v]) {
            continue;
        }
        const EmbeddedVertex& ev = e.vertices[v];
        hs[v] = ev.height_mm;
        hy[v] = s.height_at(ev.coarse_triangle, ev.barycentric, vp.uv[v], vp.piece[v]);
        ss += hs[v] * hs[v];
        sy += hy[v] * hy[v];
        ++n;
        const std::size_t c = std::size_t(s.triangles[ev.coarse_triangle].cls);
        for (std::size_t slot : {c, kWrinkleClasses}) {
            if (slot == kWrinkleClasses && c == 0) {
                continue;
            }
            auto& p = ps[slot];
            p[0] += 1;
            p[1] += hs[v];
            p[2] += hy[v];
            p[3] += hs[v] * hs[v];
            p[4] += hy[v] * hy[v];
            p[5] += hs[v] * hy[v];
        }
    }
    out.simulated_rms_height_mm = n ? std::sqrt(ss / double(n)) : 0;
    out.synthesised_rms_height_mm = n ? std::sqrt(sy / double(n)) : 0;
    const auto pearson = [](const std::array<double, 6>& p) {
        const double m = p[0];
        const double vx = p[3] - p[1] * p[1] / m, vy = p[4] - p[2] * p[2] / m;
        const double cxy = p[5] - p[1] * p[2] / m;
        return m >= 3 && vx > 0 && vy > 0 ? cxy / std::sqrt(vx * vy)
                                          : std::numeric_limits<double>::quiet_NaN();
    };
    const PatternWindows sim_w(simulated, hs);
    const PatternWindows syn_w(s.fine, s.height_mm);
    const TrainOptions& o = db.options;
    const auto dominant = [&](const WindowProfile& p) { return has_wave(p, o); };
    std::array<std::vector<double>, kWrinkleClasses + 1> lam_err, amp_err;
    for (std::size_t t = 0; t < coarse.triangles.size(); ++t) {
        const TrianglePrediction& p = s.triangles[t];
        const UV centre = pattern_centroid(coarse.uv[t]);
        const WindowProfile a =
            sim_w.profile(coarse.triangle_piece[t], centre, p.axis, 0.5 * o.window_length_mm,
                          0.5 * o.window_width_mm, o.min_periods);
        if (!a.resolved) {
            continue;
        }
        const WindowProfile b =
            syn_w.profile(coarse.triangle_piece[t], centre, p.axis, 0.5 * o.window_length_mm,
                          0.5 * o.window_width_mm, o.min_periods);
        const std::size_t c = std::size_t(p.cls);
        for (std::size_t slot : {c, kWrinkleClasses}) {
            if (slot == kWrinkleClasses && c == 0) {
                continue;
            }
            SynthesisCheckRow& row = slot == kWrinkleClasses ? out.all : out.per_class[slot];
            ++row.windows;
            if (!dominant(a)) {
                continue;
            }
            ++row.simulated;
            if (dominant(b)) {
                ++row.both;
                lam_err[slot].push_back(
                    100 * std::abs(b.spectrum.wavelength / a.spectrum.wavelength - 1));
                amp_err[slot].push_back(100 *
                                        std::abs(b.spectrum.amplitude / a.spectrum.amplitude - 1));
            } else {
                amp_err[slot].push_back(100);
            }
        }
    }
    for (std::size_t slot = 0; slot <= kWrinkleClasses; ++slot) {
        SynthesisCheckRow& row = slot == kWrinkleClasses ? out.all : out.per_class[slot];
        row.median_wavelength_error_percent = internal::median(lam_err[slot]);
        row.median_amplitude_error_percent = internal::median(amp_err[slot]);
        row.pearson_r = pearson(ps[slot]);
        row.vertices = std::size_t(ps[slot][0]);
    }
    return out;
}

/// The report as JSON (mm, seconds; NaN is null).
inline nlohmann::ordered_json synthesis_report_json(const SynthesisReport& r) {
    const auto num = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    };
    nlohmann::ordered_json j;
    j["coarse_triangles"] = r.coarse_triangles;
    j["fine_vertices"] = r.fine_vertices;
    j["fine_triangles"] = r.fine_triangles;
    j["database_samples"] = r.database_samples;
    j["displaced_vertices"] = r.displaced;
    j["rms_height_mm"] = r.rms_height_mm;
    j["max_height_mm"] = r.max_height_mm;
    for (std::size_t c = 1; c < kWrinkleClasses; ++c) {
        auto& x = j["classes"][to_string(WrinkleClass(c))];
        x["triangles_with_wrinkles"] = r.with_wrinkles[c];
        x["median_amplitude_mm"] = num(r.median_amplitude_mm[c]);
        x["median_pattern_wavelength_mm"] = num(r.median_wavelength_mm[c]);
    }
    j["damped_vertices"] = r.damped_vertices;
    j["fix_rounds_used"] = r.fix_rounds_used;
    j["new_self_crossings_left"] = r.new_self_crossings_left;
    j["new_body_contacts_left"] = r.new_body_contacts_left;
    j["body_checked"] = r.body_checked;
    if (r.check_seconds > 0) {
        for (const auto& [name, q] :
             {std::pair<const char*, const garment::QualityFigures*>{"before", &r.quality_before},
              {"after", &r.quality_after}}) {
            auto& x = j["quality"][name];
            x["vertices_inside_body"] = q->vertices_inside_body;
            x["edges_crossing_body"] = q->edges_crossing_body;
            x["self_intersections"] = q->self_intersections;
            x["stretch_p95"] = q->stretch_p95;
        }
    }
    j["synthesis_seconds"] = r.synthesis_seconds;
    j["fix_seconds"] = r.fix_seconds;
    j["check_seconds"] = r.check_seconds;
    return j;
}

/// The check as JSON (%, mm; NaN is null).
inline nlohmann::ordered_json synthesis_check_json(const SynthesisCheck& c) {
    const auto num = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    };
    const auto row = [&](const SynthesisCheckRow& r) {
        nlohmann::ordered_json j;
        j["windows"] = r.windows;
        j["simulation_has_wave"] = r.simulated;
        j["both_have_wave"] = r.both;
        j["median_wavelength_error_percent"] = num(r.median_wavelength_error_percent);
        j["median_amplitude_error_percent"] = num(r.median_amplitude_error_percent);
        j["pearson_r"] = num(r.pearson_r);
        j["vertices"] = r.vertices;
        return j;
    };
    nlohmann::ordered_json j;
    for (std::size_t k = 0; k < kWrinkleClasses; ++k) {
        j["classes"][to_string(WrinkleClass(k))] = row(c.per_class[k]);
    }
    j["compressed"] = row(c.all);
    j["simulated_rms_height_mm"] = c.simulated_rms_height_mm;
    j["synthesised_rms_height_mm"] = c.synthesised_rms_height_mm;
    return j;
}

}  // namespace tapeline::wrinkles
