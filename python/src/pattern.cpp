// tapeline.pattern: sewing patterns as dicts (the pattern JSON of `tapeline pattern export
// --json`), their files and the SQLite pattern database.
#include "common.h"

#include <tapeline/pattern/database.h>
#include <tapeline/pattern/dxf.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/png.h>
#include <tapeline/pattern/svg.h>

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline::python {

namespace {

namespace tp = tapeline::pattern;

py::dict pattern_dict(const tp::Pattern& p) {
    return to_python(tp::to_json(p)).cast<py::dict>();
}

/// A pattern dict (as pattern_dict makes) back to the model; InvalidInput as the JSON reader.
tp::Pattern pattern_of(const py::dict& d, const std::string& where) {
    return tp::from_json(json_of(d, where), where);
}

py::dict summary_dict(const tp::PatternSummary& s) {
    py::dict d;
    d["name"] = s.name;
    d["designer"] = s.designer;
    d["garment_type"] = s.garment_type;
    d["size"] = s.size;
    d["tags"] = s.tags;
    d["pieces"] = s.pieces;
    d["seams"] = s.seams;
    d["json_bytes"] = s.json_bytes;
    d["stored_bytes"] = s.stored_bytes;
    d["updated"] = s.updated;
    return d;
}

py::dict store_dict(const tp::StoreReport& r) {
    py::dict d;
    d["replaced"] = r.replaced;
    d["seconds"] = r.seconds;
    d["json_bytes"] = r.compression.json_bytes;
    d["stored_bytes"] = r.compression.stored_bytes;
    d["ratio"] = r.compression.ratio;
    d["max_error_mm"] = r.compression.max_error_mm;
    return d;
}

/// The pattern database; closed by close() or at the end of a `with` block.
class Database {
public:
    Database(const std::optional<std::string>& path, bool read_only, bool create) {
        tp::DatabaseOptions o;
        o.read_only = read_only;
        o.create = create;
        const std::string file = path ? *path : tp::default_pattern_database_path();
        InterruptGuard interrupt_guard;
        py::gil_scoped_release release;
        db_ = std::make_unique<tp::PatternDatabase>(file, o);
    }
    tp::PatternDatabase& db() {
        if (!db_) {
            throw InvalidInput("the pattern database is closed");
        }
        return *db_;
    }
    void close() { db_.reset(); }

    std::unique_ptr<tp::PatternDatabase> db_;
};

}  // namespace

void bind_pattern(py::module_& parent) {
    py::module_ m = parent.def_submodule(
        "pattern", "Sewing patterns (as dicts in the pattern JSON format) and their database.");

    m.def(
        "read",
        [](const std::string& path, const std::string& format) {
            tp::Pattern p;
            {
                InterruptGuard interrupt_guard;
                py::gil_scoped_release release;
                p = tp::read_pattern_file(path, format);
            }
            return pattern_dict(p);
        },
        py::arg("path"), py::arg("format") = "auto",
        "Reads a pattern file (FreeSewing JSON/SVG export, GarmentCode specification, Tapeline "
        "pattern JSON; format 'auto' detects it) as a pattern dict.");
    m.def(
        "write_json",
        [](const py::dict& pattern, const std::string& path) {
            tp::write_pattern_json(pattern_of(pattern, "pattern"), path);
        },
        py::arg("pattern"), py::arg("path"), "Writes a pattern dict as a pattern JSON file.");
    m.def(
        "svg",
        [](const py::dict& pattern) {
            std::ostringstream out;
            tp::write_svg(pattern_of(pattern, "pattern"), out);
            return out.str();
        },
        py::arg("pattern"),
        "The pattern drawn at 1:1 in millimetres (SVG text, as `tapeline pattern export --svg`).");
    m.def(
        "dxf",
        [](const py::dict& pattern) {
            std::ostringstream out;
            tp::write_dxf(pattern_of(pattern, "pattern"), out);
            return out.str();
        },
        py::arg("pattern"),
        "The pattern as a DXF-AAMA / ASTM D6673 file (text, as `tapeline pattern export --dxf`).");
    m.def(
        "png",
        [](const py::dict& pattern, double pixels_per_mm) {
            tp::PngOptions o;
            o.pixels_per_mm = pixels_per_mm;
            std::ostringstream out;
            tp::write_png(pattern_of(pattern, "pattern"), out, o);
            return py::bytes(out.str());
        },
        py::arg("pattern"), py::arg("pixels_per_mm") = tp::PngOptions{}.pixels_per_mm,
        "The pattern drawn as PNG bytes (as `tapeline pattern export --png`).");
    m.def(
        "raster",
        [](const py::dict& pattern, double pixels_per_mm) {
            tp::PngOptions o;
            o.pixels_per_mm = pixels_per_mm;
            const tp::RgbaImage img = tp::rasterise_pattern(pattern_of(pattern, "pattern"), o);
            py::array_t<std::uint8_t> out(
                {py::ssize_t(img.height), py::ssize_t(img.width), py::ssize_t{4}});
            std::copy(img.rgba.begin(), img.rgba.end(), out.mutable_data());
            return out;
        },
        py::arg("pattern"), py::arg("pixels_per_mm") = tp::PngOptions{}.pixels_per_mm,
        "The pattern drawn as an RGBA image, a uint8 array (height, width, 4), top row first (the "
        "pixels of png()).");
    m.def(
        "check",
        [](const py::dict& pattern) { return pattern_dict(pattern_of(pattern, "pattern")); },
        py::arg("pattern"),
        "Reads a pattern dict as the library does (InvalidInput naming what is wrong) and returns "
        "it as the library writes it.");

    py::class_<Database>(m, "Database",
                         "A SQLite pattern database (created when missing unless create=False); "
                         "path None: the per-user default.")
        .def(py::init<const std::optional<std::string>&, bool, bool>(),
             py::arg("path") = py::none(), py::arg("read_only") = false, py::arg("create") = true)
        .def_property_readonly("path", [](Database& d) { return d.db().path(); })
        .def("__len__", [](Database& d) { return d.db().count(); })
        .def("__contains__", [](Database& d, const std::string& n) { return d.db().contains(n); })
        .def(
            "list",
            [](Database& d, const std::string& name, const std::string& designer,
               const std::string& garment_type, const std::string& size,
               const std::vector<std::string>& tags) {
                tp::PatternQuery q{name, designer, garment_type, size, tags};
                py::list out;
                for (const auto& s : d.db().search(q)) {
                    out.append(summary_dict(s));
                }
                return out;
            },
            py::arg("name") = "", py::arg("designer") = "", py::arg("garment_type") = "",
            py::arg("size") = "", py::arg("tags") = std::vector<std::string>{},
            "Summaries of the stored patterns matching every given field (name and designer: "
            "case-insensitive substrings; garment type and size: exact; every tag).")
        .def(
            "get",
            [](Database& d, const std::string& name) { return pattern_dict(d.db().load(name)); },
            py::arg("name"), "The stored pattern as a dict; InvalidInput when there is none.")
        .def(
            "store",
            [](Database& d, const py::dict& pattern, bool replace) {
                const tp::Pattern p = pattern_of(pattern, "pattern");
                return store_dict(d.db().store(p, tp::StoreOptions{replace}));
            },
            py::arg("pattern"), py::arg("replace") = false,
            "Stores a pattern dict under its name (refused when the name exists, unless replace).")
        .def(
            "import_file",
            [](Database& d, const std::string& path, const std::string& format, bool replace) {
                tp::Pattern p;
                {
                    InterruptGuard interrupt_guard;
                    py::gil_scoped_release release;
                    p = tp::read_pattern_file(path, format);
                }
                py::dict r = store_dict(d.db().store(p, tp::StoreOptions{replace}));
                r["name"] = p.name;
                return r;
            },
            py::arg("path"), py::arg("format") = "auto", py::arg("replace") = false,
            "Reads a pattern file and stores it (as `tapeline pattern import`).")
        .def(
            "remove", [](Database& d, const std::string& name) { return d.db().remove(name); },
            py::arg("name"), "Removes a pattern; False when there was none.")
        .def("close", &Database::close)
        .def("__enter__", [](py::object self) { return self; })
        .def("__exit__", [](Database& d, const py::args&) { d.close(); });
}

}  // namespace tapeline::python
