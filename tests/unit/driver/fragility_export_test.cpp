// Exporting fragility fits: Hdf5Reader reads back what Hdf5Writer writes; read_fragility_fits
// reads a file in the study output's layout (written here with Hdf5Writer) in the order of
// severity and refuses what is not one; the writers' texts (pelicun's CSV to the character,
// OpenQuake's units, IMTs and moments) and their refusals; OpenQuake's mean and stddev give back
// median and beta. (tests/cli/export_test.py runs the command on files h5py writes.)
#include "mpi_driver/io/fragility_export.hpp"

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "mpi_driver/io/fragility_fits.hpp"
#include "mpi_driver/io/hdf5_file.hpp"
#include "mpi_driver/io/hdf5_reader.hpp"
#include "mpi_driver/io/isolated_fits.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

using testing::TemporaryFolder;

const double nan = std::numeric_limits<double>::quiet_NaN();

// Expects `call` to throw InvalidInput whose message holds every fragment.
template <typename Call>
void expect_export_refused(Call call, const std::vector<std::string>& fragments) {
  try {
    call();
    ADD_FAILURE() << "no InvalidInput";
  } catch (const InvalidInput& error) {
    for (const auto& fragment : fragments) {
      EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
          << "\"" << error.what() << "\" lacks \"" << fragment << "\"";
    }
  }
}

struct StateSpec {
  std::string name;
  std::string type;
  double threshold;
  double median;
  double beta;
  std::string status = "ok";
};

// A study output's root marks and /fragility, as study_output.cpp lays them out.
void write_fits_file(const std::filesystem::path& path, const std::vector<StateSpec>& states,
                     const std::string& severity_order, bool fragility = true,
                     const std::string& config_hash = "00000000deadbeef",
                     const std::string& im_label = "PGA") {
  Hdf5Writer file(path);
  file.set_attribute("/", "config", std::string("{\"seed\": 7}"));
  file.set_attribute("/", "config_hash", config_hash);
  if (fragility) {
    file.create_group("/fragility");
    file.set_attribute("/fragility", "im_name", std::string("pga"));
    file.set_attribute("/fragility", "im_units", std::string("g"));
    file.set_attribute("/fragility", "im_label", im_label);
    if (!severity_order.empty()) {
      file.set_attribute("/fragility", "severity_order", severity_order);
    }
    file.set_attribute("/fragility", "crossing_pairs", std::string("overturn,rock_half"));
    for (const auto& state : states) {
      const std::string group = "/fragility/" + state.name;
      file.create_group(group);
      file.set_attribute(group, "type", state.type);
      file.set_attribute(group, "threshold", state.threshold);
      file.set_attribute(group, "median", state.median);
      file.set_attribute(group, "beta", state.beta);
      file.set_attribute(group, "fit_status", state.status);
      file.set_attribute(group, "deviance", 2.5);
      if (state.type == "residual_slide") {
        file.set_attribute(group, "overturned_exceeds", std::int64_t{0});
      }
      file.write_column(group + "/im", std::vector<double>{0.25, 0.5, 0.75, 1.0});
    }
  }
  file.close();
}

const std::vector<StateSpec> three_states = {
    {"overturn", "overturning", 0.0, 1.5, 0.25},
    {"slide_5cm", "residual_slide", 0.05, 0.6, 0.4},
    {"rock_half", "max_rotation", 0.5, 0.9, 0.3},
};

TEST(Hdf5Reader, ReadsWhatTheWriterWrites) {
  TemporaryFolder folder;
  const auto path = folder.path() / "f.h5";
  {
    Hdf5Writer file(path);
    file.set_attribute("/", "text", std::string("caf\xc3\xa9, 5 %"));
    file.set_attribute("/", "count", std::int64_t{42});
    file.create_group("/g");
    file.create_group("/g/inner");
    file.set_attribute("/g", "x", 0.1);
    file.write_column("/g/values", std::vector<double>{1.5, -2.25, 1e-300});
    file.write_column("/g/counts", std::vector<std::int64_t>{3, 4});
    file.write_column("/g/empty", std::vector<double>{});
    file.close();
  }
  EXPECT_TRUE(Hdf5Reader::is_hdf5(path));
  const Hdf5Reader reader(path);
  EXPECT_EQ(reader.string_attribute("/", "text", 64), "caf\xc3\xa9, 5 %");
  EXPECT_EQ(reader.number_attribute("/", "count"), 42.0);
  EXPECT_EQ(reader.number_attribute("/g", "x"), 0.1);
  EXPECT_EQ(reader.number_dataset("/g/values", 3), (std::vector<double>{1.5, -2.25, 1e-300}));
  EXPECT_EQ(reader.number_dataset("/g/counts", 2), (std::vector<double>{3.0, 4.0}));
  EXPECT_TRUE(reader.number_dataset("/g/empty", 0).empty());
  EXPECT_EQ(reader.member_names("/g"),
            (std::vector<std::string>{"counts", "empty", "inner", "values"}));
  EXPECT_TRUE(reader.has_object("/"));
  EXPECT_TRUE(reader.has_object("/g/inner"));
  EXPECT_FALSE(reader.has_object("/missing/deeper"));
  EXPECT_FALSE(reader.has_object("relative"));
  EXPECT_TRUE(reader.is_group("/g/inner"));
  EXPECT_FALSE(reader.is_group("/g/values"));
  EXPECT_TRUE(reader.has_attribute("/g", "x"));
  EXPECT_FALSE(reader.has_attribute("/g", "y"));
  EXPECT_FALSE(reader.has_attribute("/missing", "x"));
  EXPECT_THROW(reader.number_attribute("/", "text"), Hdf5ReadError);
  EXPECT_THROW(reader.string_attribute("/", "count", 64), Hdf5ReadError);
  EXPECT_THROW(reader.number_dataset("/g/missing", 1), Hdf5ReadError);
}

TEST(Hdf5Reader, TellsHdf5FromOtherFiles) {
  TemporaryFolder folder;
  std::ofstream(folder.path() / "text.h5") << "not HDF5\n";
  EXPECT_FALSE(Hdf5Reader::is_hdf5(folder.path() / "text.h5"));
  EXPECT_FALSE(Hdf5Reader::is_hdf5(folder.path() / "absent.h5"));
  EXPECT_THROW(Hdf5Reader(folder.path() / "text.h5"), Hdf5ReadError);
}

TEST(FragilityFits, ReadsTheStatesInSeverityOrder) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5";
  // rock_half is not in severity_order: it follows the states it names.
  write_fits_file(path, three_states, "slide_5cm, overturn");
  const FragilityFits fits = read_fragility_fits(path);
  EXPECT_EQ(fits.source, path.string());
  EXPECT_EQ(fits.config_hash, "00000000deadbeef");
  EXPECT_EQ(fits.im_name, "pga");
  EXPECT_EQ(fits.im_units, "g");
  EXPECT_EQ(fits.im_label, "PGA");
  EXPECT_FALSE(fits.im_period_s);
  ASSERT_EQ(fits.states.size(), 3u);
  EXPECT_EQ(fits.states[0].name, "slide_5cm");
  EXPECT_EQ(fits.states[1].name, "overturn");
  EXPECT_EQ(fits.states[2].name, "rock_half");
  const FragilityFit& slide = fits.states[0];
  EXPECT_EQ(slide.type, "residual_slide");
  EXPECT_EQ(slide.threshold, 0.05);
  EXPECT_EQ(slide.median, 0.6);
  EXPECT_EQ(slide.beta, 0.4);
  EXPECT_TRUE(slide.fitted());
  EXPECT_EQ(slide.deviance, 2.5);
  EXPECT_FALSE(slide.gof_p_value);
  EXPECT_TRUE(slide.median_ci.empty());
  EXPECT_FALSE(slide.overturned_exceeds);
  EXPECT_TRUE(fits.states[1].overturned_exceeds);
  ASSERT_EQ(fits.crossing_pairs.size(), 1u);
  EXPECT_EQ(fits.crossing_pairs[0].first, "overturn");
  EXPECT_EQ(fits.crossing_pairs[0].second, "rock_half");
  EXPECT_EQ(slide.im, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
}

// Export reads in a child process; the fits come back as they are read, NaN and all.
TEST(FragilityFits, ReadInAChildTheSame) {
  TemporaryFolder folder;
  const auto path = folder.path() / "study.h5";
  auto states = three_states;
  states.push_back({"a_never", "residual_slide", 0.5, nan, nan, "no_exceedances"});
  write_fits_file(path, states, "slide_5cm,rock_half,overturn");
  const FragilityFits direct = read_fragility_fits(path);
  const FragilityFits isolated = read_fragility_fits_isolated(path, std::chrono::seconds(10));
  EXPECT_EQ(isolated.source, direct.source);
  EXPECT_EQ(isolated.config_hash, direct.config_hash);
  EXPECT_EQ(isolated.im_label, direct.im_label);
  EXPECT_EQ(isolated.im_period_s, direct.im_period_s);
  EXPECT_EQ(isolated.crossing_pairs, direct.crossing_pairs);
  ASSERT_EQ(isolated.states.size(), direct.states.size());
  for (std::size_t k = 0; k < direct.states.size(); ++k) {
    const auto& a = isolated.states[k];
    const auto& b = direct.states[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.fit_status, b.fit_status);
    EXPECT_EQ(a.threshold, b.threshold);
    EXPECT_TRUE(a.median == b.median || (std::isnan(a.median) && std::isnan(b.median))) << a.name;
    EXPECT_TRUE(a.beta == b.beta || (std::isnan(a.beta) && std::isnan(b.beta))) << a.name;
    EXPECT_EQ(a.deviance, b.deviance);
    EXPECT_EQ(a.gof_p_value, b.gof_p_value);
    EXPECT_EQ(a.overturned_exceeds, b.overturned_exceeds);
    EXPECT_EQ(a.im, b.im);
  }
  write_fits_file(folder.path() / "twice.h5", three_states, "overturn,overturn");
  expect_export_refused(
      [&] { read_fragility_fits_isolated(folder.path() / "twice.h5", std::chrono::seconds(10)); },
      {"twice.h5", "twice"});
}

TEST(FragilityFits, WithoutSeverityOrderSortsByMedianUnfittedLast) {
  TemporaryFolder folder;
  auto states = three_states;
  states.push_back({"a_never", "residual_slide", 0.5, nan, nan, "no exceedance at any level"});
  write_fits_file(folder.path() / "study.h5", states, "");
  const FragilityFits fits = read_fragility_fits(folder.path() / "study.h5");
  ASSERT_EQ(fits.states.size(), 4u);
  EXPECT_EQ(fits.states[0].name, "slide_5cm");
  EXPECT_EQ(fits.states[1].name, "rock_half");
  EXPECT_EQ(fits.states[2].name, "overturn");
  EXPECT_EQ(fits.states[3].name, "a_never");
  EXPECT_FALSE(fits.states[3].fitted());
}

TEST(FragilityFits, RefusesWhatIsNotAStudyOutputWithFits) {
  TemporaryFolder folder;
  const auto& dir = folder.path();
  std::ofstream(dir / "notes.txt") << "hello\n";
  expect_export_refused([&] { read_fragility_fits(dir / "notes.txt"); },
                        {"notes.txt", "not an HDF5"});
  expect_export_refused([&] { read_fragility_fits(dir / "absent.h5"); },
                        {"absent.h5", "no such file"});
  expect_export_refused([&] { read_fragility_fits(dir); }, {"folder"});
  {
    Hdf5Writer other(dir / "other.h5");
    other.set_attribute("/", "title", std::string("someone else's"));
    other.close();
  }
  expect_export_refused([&] { read_fragility_fits(dir / "other.h5"); },
                        {"other.h5", "not a blockfrag study output"});
  write_fits_file(dir / "bare.h5", {}, "", false);
  expect_export_refused([&] { read_fragility_fits(dir / "bare.h5"); }, {"bare.h5", "/fragility"});
  write_fits_file(dir / "wrong.h5", three_states, "overturn,landslide");
  expect_export_refused([&] { read_fragility_fits(dir / "wrong.h5"); }, {"wrong.h5", "landslide"});
  write_fits_file(dir / "twice.h5", three_states, "overturn,overturn");
  expect_export_refused([&] { read_fragility_fits(dir / "twice.h5"); }, {"twice.h5", "twice"});
  write_fits_file(dir / "nan.h5", {{"overturn", "overturning", 0.0, nan, 0.3}}, "overturn");
  expect_export_refused([&] { read_fragility_fits(dir / "nan.h5"); },
                        {"nan.h5", "/fragility/overturn"});
}

// What the exported files would carry: a limit-state name that splits OpenQuake's <limitStates>
// or breaks the XML, a text with control characters, a config hash that is not one, a fit whose
// OpenQuake moments overflow or underflow, levels that are not levels. Each is refused naming the
// file and the object, quoting no more than a short printable excerpt.
TEST(FragilityFits, RefusesWhatWouldMakeAnInvalidExport) {
  TemporaryFolder folder;
  const auto& dir = folder.path();
  const auto refused = [&](const std::string& file, const std::vector<StateSpec>& states,
                           const std::string& order, const std::vector<std::string>& fragments,
                           const std::string& hash = "00000000deadbeef",
                           const std::string& label = "PGA") {
    write_fits_file(dir / file, states, order, true, hash, label);
    expect_export_refused([&] { read_fragility_fits(dir / file); }, fragments);
  };
  // The name as the message quotes it: bytes outside printable ASCII become '?'.
  for (const auto& [name, shown] :
       {std::pair{"over turn", "over turn"}, std::pair{"over\nturn", "over?turn"},
        std::pair{"over\x01turn", "over?turn"}, std::pair{"over\xffturn", "over?turn"}}) {
    refused(
        "name.h5", {{name, "overturning", 0.0, 1.5, 0.25}}, name,
        {"name.h5", "/fragility has a member \"" + std::string(shown) + "\"", "limit state name"});
    std::filesystem::remove(dir / "name.h5");
  }
  refused("beta_40.h5", {{"overturn", "overturning", 0.0, 1.5, 40.0}}, "overturn",
          {"beta_40.h5", "/fragility/overturn", "beta 40", "[1e-06, 10]"});
  refused("beta_denormal.h5", {{"overturn", "overturning", 0.0, 1.5, 5e-324}}, "overturn",
          {"beta_denormal.h5", "beta 5e-324"});
  refused("median_huge.h5", {{"overturn", "overturning", 0.0, 1e300, 0.3}}, "overturn",
          {"median_huge.h5", "median 1e+300"});
  refused("threshold.h5", {{"slide", "residual_slide", nan, 1.5, 0.3}}, "slide",
          {"threshold.h5", "/fragility/slide", "threshold nan"});
  refused("hash.h5", three_states, "", {"hash.h5", "config_hash", "\"=cmd|x\"", "16 hexadecimal"},
          "=cmd|x");
  refused("long_hash.h5", three_states, "", {"long_hash.h5", "config_hash", "more than 64"},
          std::string(1000, 'a'));
  refused("label.h5", three_states, "", {"label.h5", "im_label", "\"PGA?<x\""}, "00000000deadbeef",
          "PGA\n<x");
  const std::string long_type(60'000, 'x');
  refused("type.h5", {{"overturn", long_type, 0.0, 1.5, 0.3}}, "overturn",
          {"type.h5", "attribute type of /fragility/overturn", "60000 bytes long"});
  try {
    read_fragility_fits(dir / "type.h5");
  } catch (const InvalidInput& error) {
    EXPECT_LT(std::string(error.what()).size(), 300u);
  }
  refused("pairs.h5", {{"overturn", "overturning", 0.0, 1.5, 0.25}}, "overturn",
          {"pairs.h5", "crossing_pairs", "\"overturn,rock_half\"", "not two of its limit states"});
}

TEST(FragilityFits, RefusesLevelsThatAreNotLevels) {
  TemporaryFolder folder;
  const auto path = folder.path() / "levels.h5";
  {
    Hdf5Writer file(path);
    file.set_attribute("/", "config", std::string("{}"));
    file.set_attribute("/", "config_hash", std::string("00000000deadbeef"));
    file.create_group("/fragility");
    for (const char* name : {"im_name", "im_units", "im_label"}) {
      file.set_attribute("/fragility", name, std::string("pga"));
    }
    file.create_group("/fragility/overturn");
    file.set_attribute("/fragility/overturn", "type", std::string("overturning"));
    file.set_attribute("/fragility/overturn", "fit_status", std::string("ok"));
    for (const char* name : {"threshold", "median", "beta"}) {
      file.set_attribute("/fragility/overturn", name, 0.5);
    }
    file.write_column("/fragility/overturn/im", std::vector<double>{0.5, 0.0, 1.0});
    file.close();
  }
  expect_export_refused([&] { read_fragility_fits(path); },
                        {"levels.h5", "/fragility/overturn/im", "the level 0"});
}

FragilityFits some_fits(const std::string& im_name, const std::string& units) {
  FragilityFits fits;
  fits.source = "study.h5";
  fits.config_hash = "00000000deadbeef";
  fits.im_name = im_name;
  fits.im_units = units;
  fits.im_label = im_name;
  for (const auto& [name, median, beta] :
       {std::tuple{"slide_2cm", 0.5, 0.4}, std::tuple{"overturn", 1.25, 0.3}}) {
    FragilityFit fit;
    fit.name = name;
    fit.type = std::string(name) == "overturn" ? "overturning" : "residual_slide";
    fit.threshold = fit.type == "overturning" ? 0.0 : 0.02;
    fit.median = median;
    fit.beta = beta;
    fit.fit_status = "ok";
    fit.im = {0.2, 0.4, 0.8, 1.6};
    fits.states.push_back(fit);
  }
  return fits;
}

TEST(FragilityExport, PelicunCsvToTheCharacter) {
  const auto model = pelicun_damage_model(some_fits("pga", "g"), "BF.TEST.1");
  EXPECT_EQ(model.csv,
            "ID,Incomplete,Demand-Type,Demand-Unit,Demand-Offset,Demand-Directional,LS1-Family,"
            "LS1-Theta_0,LS1-Theta_1,LS2-Family,LS2-Theta_0,LS2-Theta_1\n"
            "BF.TEST.1,0,Peak Ground Acceleration,g,0,1,lognormal,0.5,0.4,lognormal,1.25,0.3\n");
  EXPECT_NE(model.json.find("\"_GeneralInformation\""), std::string::npos);
  EXPECT_NE(model.json.find("\"LS2\": {\n        \"DS2\": {\n          \"Description\": "
                            "\"overturn: overturned\""),
            std::string::npos)
      << model.json;
  EXPECT_NE(model.json.find("\"slide_2cm: residual slide > 0.02 m, or overturned\""),
            std::string::npos);
}

TEST(FragilityExport, MeasuresAsEachToolNamesThem) {
  const auto pgv = some_fits("pgv", "m/s");
  EXPECT_NE(pelicun_damage_model(pgv, "B").csv.find(",Peak Ground Velocity,mps,0,1,"),
            std::string::npos);
  const std::string nrml = openquake_fragility_model(pgv, "B");
  EXPECT_NE(nrml.find("<imls imt=\"PGV\" minIML=\"20\" maxIML=\"160\" noDamageLimit=\"0\"/>"),
            std::string::npos)
      << nrml;
  auto sa = some_fits("sa", "g");
  sa.im_period_s = 0.25;
  sa.im_damping = 0.05;
  EXPECT_NE(pelicun_damage_model(sa, "B").csv.find(",Peak Spectral Acceleration|0.25,g,"),
            std::string::npos);
  EXPECT_NE(openquake_fragility_model(sa, "B").find("imt=\"SA(0.25)\""), std::string::npos);
  sa.im_period_s = 2.0;
  EXPECT_NE(openquake_fragility_model(sa, "B").find("imt=\"SA(2.0)\""), std::string::npos);
  EXPECT_NE(pelicun_damage_model(sa, "B").csv.find("Peak Spectral Acceleration|2.0,"),
            std::string::npos);
}

TEST(FragilityExport, OpenQuakeMomentsGiveBackMedianAndBeta) {
  for (const double median : {0.05, 0.89, 1.0, 37.5}) {
    for (const double beta : {0.05, 0.3, 0.8, 1.5}) {
      const LognormalMoments moments = lognormal_moments(median, beta);
      EXPECT_DOUBLE_EQ(moments.mean, median * std::exp(beta * beta / 2.0));
      const double ratio_squared = std::pow(moments.stddev / moments.mean, 2);
      EXPECT_NEAR(moments.mean / std::sqrt(1.0 + ratio_squared), median, 1e-13 * median);
      EXPECT_NEAR(std::sqrt(std::log1p(ratio_squared)), beta, 1e-12 * beta);
    }
  }
  const std::string nrml = openquake_fragility_model(some_fits("pga", "g"), "BF.TEST.1");
  const LognormalMoments first = lognormal_moments(0.5, 0.4);
  EXPECT_NE(nrml.find("<params ls=\"slide_2cm\" mean=\"" + exact_number(first.mean) +
                      "\" stddev=\"" + exact_number(first.stddev) + "\"/>"),
            std::string::npos)
      << nrml;
  EXPECT_NE(nrml.find("<limitStates>slide_2cm overturn</limitStates>"), std::string::npos);
  EXPECT_NE(nrml.find("<fragilityModel id=\"BF_TEST_1\""), std::string::npos);
  EXPECT_NE(nrml.find("<fragilityFunction id=\"BF.TEST.1\" format=\"continuous\" "
                      "shape=\"logncdf\">"),
            std::string::npos);
  EXPECT_LT(nrml.find("slide_2cm\" mean"), nrml.find("overturn\" mean"));
}

TEST(FragilityExport, ExactNumbersReadBackTheSame) {
  for (const double value : {0.1, 1.0 / 3.0, 1e-300, 123456.789, 2.5e-320, 0.8912345678901234}) {
    const std::string text = exact_number(value);
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    EXPECT_EQ(back, value) << text;
  }
  EXPECT_EQ(exact_number(0.5), "0.5");
  EXPECT_EQ(exact_number(20.0), "20");
}

TEST(FragilityExport, RefusesMeasuresTheToolsDoNotKnow) {
  auto fits = some_fits("pga_over_g_tan_alpha", "1");
  fits.im_label = "PGA/(g tan alpha)";
  expect_export_refused([&] { pelicun_damage_model(fits, "B"); },
                        {"study.h5", "PGA/(g tan alpha)", "dimensionless", "pelicun"});
  expect_export_refused([&] { openquake_fragility_model(fits, "B"); }, {"study.h5", "OpenQuake"});
  auto pulse = some_fits("pulse_amplitude", "g");
  pulse.im_label = "pulse amplitude";
  try {
    openquake_fragility_model(pulse, "B");
    ADD_FAILURE() << "the pulse amplitude is exported";
  } catch (const InvalidInput& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("is the pulse amplitude, which neither"), std::string::npos) << message;
    EXPECT_EQ(message.find("(pulse amplitude)"), std::string::npos) << message;
  }
  expect_export_refused([&] { pelicun_damage_model(some_fits("pga", "m/s"), "B"); }, {"m/s"});
  auto sa = some_fits("sa", "g");
  sa.im_period_s = 1.0;
  sa.im_damping = 0.02;
  expect_export_refused([&] { openquake_fragility_model(sa, "B"); }, {"2 %", "5 %"});
  sa.im_damping.reset();
  expect_export_refused([&] { pelicun_damage_model(sa, "B"); }, {"damping"});
  sa.im_period_s.reset();
  expect_export_refused([&] { pelicun_damage_model(sa, "B"); }, {"period"});
}

TEST(FragilityExport, ExportableFitsRefuseOrLeaveOutUnfittedStates) {
  auto fits = some_fits("pga", "g");
  FragilityFit never = fits.states[0];
  never.name = "slide_1m";
  never.median = nan;
  never.beta = nan;
  never.fit_status = "no exceedance at any level";
  fits.states.push_back(never);
  std::vector<std::string> left_out;
  expect_export_refused([&] { exportable_fits(fits, false, left_out); },
                        {"study.h5", "slide_1m", "no exceedance at any level", "--fitted-only"});
  left_out.clear();
  const FragilityFits kept = exportable_fits(fits, true, left_out);
  EXPECT_EQ(left_out, std::vector<std::string>{"slide_1m"});
  ASSERT_EQ(kept.states.size(), 2u);
  EXPECT_EQ(kept.states[1].name, "overturn");

  FragilityFits none = fits;
  none.states = {never};
  expect_export_refused([&] { exportable_fits(none, true, left_out); }, {"nothing to export"});

  FragilityFits swapped = some_fits("pga", "g");
  std::swap(swapped.states[0], swapped.states[1]);
  expect_export_refused([&] { exportable_fits(swapped, false, left_out); },
                        {"not in order of severity", "overturn"});
}

TEST(FragilityExport, IdsAndDescriptions) {
  EXPECT_EQ(default_export_id(some_fits("pga", "g")), "BF.BLOCK.00000000deadbeef");
  EXPECT_NO_THROW(check_export_id("BF.BLOCK.001"));
  EXPECT_NO_THROW(check_export_id("block_7"));
  for (const std::string& bad :
       std::vector<std::string>{"", "BF-1", "BF BLOCK", ".BF", "BF.", std::string(76, 'a')}) {
    EXPECT_THROW(check_export_id(bad), InvalidInput) << bad;
  }
  FragilityFit fit;
  fit.type = "max_rotation";
  fit.threshold = 0.5;
  EXPECT_EQ(limit_state_description(fit), "max |theta| > 0.5 alpha, or overturned");
  fit.type = "residual_slide";
  fit.threshold = 0.05;
  EXPECT_EQ(limit_state_description(fit), "residual slide > 0.05 m, or overturned");
  fit.overturned_exceeds = false;
  EXPECT_EQ(limit_state_description(fit), "residual slide > 0.05 m");
  fit.type = "max_rotation";
  EXPECT_EQ(limit_state_description(fit), "max |theta| > 0.05 alpha");
  fit.type = "overturning";
  EXPECT_EQ(limit_state_description(fit), "overturned");
}

}  // namespace
}  // namespace blockfrag
