// A body-measurement set (name → millimetres; angles in degrees) and a Seamly2D multisize table.
//
// Names are kept as their source spells them (ours "bust_girth", FreeSewing "chest", Seamly2D
// "bust_circ"); catalogue.h relates them. Seamly2D multisize tables are linear in size and
// height: value(size, height) = base + (size − base_size)/size_step · size_increase
// + (height − base_height)/height_step · height_increase.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::sizes {

/// A named set of body measurements, keyed by measurement name.
struct MeasurementSet {
    std::string name;                      ///< set name (file stem or set key)
    std::string source;                    ///< file it came from
    std::map<std::string, double> values;  ///< mm (angles: degrees)
    /// Measurements of the file that have no value, with the reason (a Seamly2D formula that
    /// refers to a name the file does not define).
    std::map<std::string, std::string> left_out;

    /// The value of `key`, or nullopt when the set lacks it.
    std::optional<double> get(const std::string& key) const {
        const auto it = values.find(key);
        return it == values.end() ? std::nullopt : std::optional<double>(it->second);
    }
};

/// Measurements in the order they were taken (a set's map sorts them by name); what the writers
/// take, so that a file lists them as the measuring did.
using NamedValues = std::vector<std::pair<std::string, double>>;

/// The values of `set`, by name.
inline NamedValues named_values(const MeasurementSet& set) {
    return NamedValues(set.values.begin(), set.values.end());
}

/// One row of a multisize table, in mm.
struct MultisizeEntry {
    double base = 0;             ///< value at the base size and height
    double size_increase = 0;    ///< change per size step
    double height_increase = 0;  ///< change per height step
};

/// A Seamly2D multisize table (.vst), in mm; sizes and heights in the file's numbers.
struct MultisizeTable {
    std::string name;    ///< table name (file stem)
    std::string source;  ///< file it came from
    /// Base size and height of the table.
    ///@{
    double base_size = 0, base_height = 0;
    ///@}
    /// Steps between sizes and between heights.
    ///@{
    double size_step = 0, height_step = 0;
    ///@}
    std::map<std::string, MultisizeEntry> entries;  ///< rows by measurement name

    /// The individual set for one size and height.
    MeasurementSet at(double size, double height) const {
        MeasurementSet m;
        m.source = source;
        m.name = name + " size " + std::to_string(size) + " height " + std::to_string(height);
        for (const auto& [k, e] : entries) {
            m.values[k] = e.base + (size - base_size) / size_step * e.size_increase +
                          (height - base_height) / height_step * e.height_increase;
        }
        return m;
    }
};

namespace internal {

inline std::string file_stem(const std::string& path) {
    std::string stem = path.substr(path.find_last_of('/') + 1);
    return stem.substr(0, stem.find_last_of('.'));
}

}  // namespace internal

}  // namespace tapeline::sizes
