// Every measurement `tapeline measure` takes or reports missing is a row of the catalogue
// (tapeline/sizes/catalogue.h) or a side of one, and carries the catalogue's columns; its kind
// agrees with the catalogue's (a width is measured as a length along the skin). Measured on the
// bundled body with its lengths along the skin, as the command does.
#include <tapeline/sizes/catalogue.h>
#include <tapeline_test/measurement.h>

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

namespace {

using namespace tapeline_test::measurement;
namespace ts = tapeline::sizes;

const char* kind_measured_as(ts::MeasurementKind k) {
    return k == ts::MeasurementKind::width ? "length" : ts::to_string(k);
}

TEST(CatalogueNames, EveryMeasuredNameIsInTheCatalogue) {
    const std::string path = std::string(TAPELINE_DATA_DIR) + "/bodies/mh_female_average.obj";
    ASSERT_TRUE(std::ifstream(path)) << path;
    BodyOptions o;
    o.unit = LengthUnit::dm;
    o.name = path;
    const LengthsResult r = measure_file_with_lengths(path, o);
    const auto& set = r.result.measurements;
    ASSERT_GE(set.measurements.size(), 40u);
    std::set<std::string> rows;
    for (const Measurement& m : set.measurements) {
        const ts::CatalogueMatch c = ts::find_measurement(m.name);
        ASSERT_TRUE(c) << m.name << " is not in the catalogue";
        rows.insert(c.entry->name);
        EXPECT_STREQ(to_string(m.kind), kind_measured_as(c.entry->kind)) << m.name;
        EXPECT_EQ(m.iso_clause, c.entry->iso_title) << m.name;
        EXPECT_EQ(m.iso_number, c.entry->iso_number) << m.name;
        EXPECT_EQ(m.freesewing, c.whole() ? c.entry->freesewing : "") << m.name;
    }
    for (const MissingMeasurement& m : set.missing) {
        const ts::CatalogueMatch c = ts::find_measurement(m.name);
        ASSERT_TRUE(c) << m.name << " is not in the catalogue";
        rows.insert(c.entry->name);
    }
    // And the catalogue holds nothing the measuring does not try.
    for (const ts::CatalogueEntry& e : ts::catalogue()) {
        EXPECT_EQ(rows.count(e.name), 1u) << e.name << " is not measured";
    }
}

}  // namespace
