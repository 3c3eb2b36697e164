// One run owns its output folder and never publishes, keeps or mixes a wrong result (io/RunFolder, io/AtomicFile,
// app/Interrupt): a write cut off by the file-size limit is a failed run naming the file; a rerun killed mid-analysis
// leaves no earlier result behind, only a summary saying `running`; a second run into a busy folder is refused naming
// the first; a read-only folder is refused before the analysis; Ctrl-C while writing leaves complete files and a
// summary saying `cancelled`; a factor beyond the address-space limit is `error` "out of memory" with its size; and
// every summary says which run made it (start, command, the project's SHA-256).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_run_folder {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const std::string kSamples = ROLLSIM_SOURCE_DIR "/samples/";

json sample(const std::string& name) { return json::parse(read_text(kSamples + name + ".json")); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
json summary_in(const std::string& out) {
  const std::string text = read_text(out + "/summary.json");
  return text.empty() ? json() : json::parse(text);
}
std::vector<std::string> temporaries(const std::string& dir) {
  std::vector<std::string> t;
  for (const std::string& n : list_dir(dir))
    if (n.size() > 4 && n[0] == '.' && n.compare(n.size() - 4, 4, ".tmp") == 0) t.push_back(n);
  return t;
}

/// A project file in a fresh folder; its path.
std::string project_file(const json& project, const std::string& tag) {
  const std::string file = make_temp_dir(tag) + "/p.json";
  write_text(file, project.dump(1));
  return file;
}

/// The main job, shorter: 20 mm of travel, every increment written (21 VTU files).
json short_pass() {
  json j = sample("rolling-2d-36x6");
  j["process"]["travel"] = 20;
  j["output"] = {{"increments", "all"}};
  return j;
}

std::string sh_quote(const std::string& s) { return "'" + s + "'"; }
}  // namespace

// The reported case: `(ulimit -f 50; trap '' XFSZ; rollsim run …)` exited 0, `converged`, with result.vtu cut off.
TEST(RunFolder, AWriteCutOffByTheFileSizeLimitIsAFailedRunNamingTheFile) {
  const std::string file = project_file(sample("block-indent-2d-50x30"), "fsize"),
                    out = fs::path(file).parent_path() / "o";
  const RunResult r = run_program("/bin/sh", {"-c", "ulimit -f 50; trap '' XFSZ; exec " + sh_quote(ROLLSIM_BINARY) +
                                                        " run " + sh_quote(file) + " --out " + sh_quote(out)});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const json s = summary_in(out);
  EXPECT_EQ(s.value("status", ""), "error");
  const std::string m = s.value("message", "");
  EXPECT_TRUE(contains(m, "result.vtu") && contains(m, "File too large")) << m;
  EXPECT_TRUE(contains(r.err, "File too large")) << r.err;
  EXPECT_FALSE(fs::exists(out + "/result.vtu")) << "a cut-off file was published under its final name";
  EXPECT_TRUE(temporaries(out).empty());
  fs::remove_all(fs::path(file).parent_path());
}

// The reported case: a rerun killed mid-analysis left the earlier run's `converged` results, indistinguishable.
TEST(RunFolder, ARerunKilledMidAnalysisLeavesNoEarlierResultAndSaysRunning) {
  json project = sample("block-indent-2d-50x30");
  const std::string file = project_file(project, "killed"), out = fs::path(file).parent_path() / "o";
  ASSERT_EQ(run_rollsim({"run", file, "--out", out, "--quiet"}).exit_code, 0);
  ASSERT_TRUE(fs::exists(out + "/result.vtu"));
  const std::string edited = project_file(short_pass(), "killed-edit");
  const RunResult killed = run_program_on_marker(ROLLSIM_BINARY, {"run", edited, "--out", out}, "assemble",
                                                 [](int pid) { kill(pid, SIGKILL); });
  EXPECT_EQ(killed.signal, SIGKILL) << killed.err;
  EXPECT_EQ(list_dir(out), std::vector<std::string>{"summary.json"}) << "the earlier run's results must be gone";
  const json s = summary_in(out);
  EXPECT_EQ(s.value("status", ""), "running");
  EXPECT_TRUE(contains(s["run"].value("command", ""), edited)) << s.dump(1);
  fs::remove_all(fs::path(file).parent_path());
  fs::remove_all(fs::path(edited).parent_path());
}

// The reported case: two runs into one folder mixed their files, and the second deleted the first's results.
TEST(RunFolder, ASecondRunIntoABusyFolderIsRefusedNamingTheFirst) {
  const std::string file = project_file(short_pass(), "busy"), out = fs::path(file).parent_path() / "o";
  RunResult second;
  const RunResult first = run_program_on_marker(ROLLSIM_BINARY, {"run", file, "--out", out}, "assemble", [&](int pid) {
    second = run_rollsim({"run", file, "--out", out, "--quiet"});
    second.out = std::to_string(pid);  // the first's pid, which the refusal must name
  });
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_TRUE(contains(second.err, "is in use by the run started")) << second.err;
  EXPECT_TRUE(contains(second.err, "pid " + second.out)) << second.err;
  EXPECT_EQ(first.exit_code, 0) << first.err;
  const json s = summary_in(out);
  EXPECT_EQ(s.value("status", ""), "converged");
  EXPECT_EQ(std::to_string(s["run"].value("pid", 0)), second.out) << "the summary is the first run's";
  EXPECT_TRUE(fs::exists(out + "/results_0020.vtu") && fs::exists(out + "/rolling.csv"));
  fs::remove_all(fs::path(file).parent_path());
}

// The reported case: a read-only output folder was found only after the whole analysis, every result lost.
TEST(RunFolder, AReadOnlyFolderIsRefusedBeforeTheAnalysis) {
  const std::string file = project_file(short_pass(), "readonly"), out = fs::path(file).parent_path() / "o";
  fs::create_directories(out);
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  const RunResult r = run_rollsim({"run", file, "--out", out});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "read-only") && contains(r.err, "before the analysis")) << r.err;
  EXPECT_FALSE(contains(r.err, "assemble")) << "nothing may be computed: " << r.err;
  EXPECT_TRUE(list_dir(out).empty());
  fs::permissions(out, fs::perms::owner_all);
  fs::remove_all(fs::path(file).parent_path());
}

// The reported case: Ctrl-C while the results were written killed the run at once, leaving result.vtu, a temporary
// and no summary.
TEST(RunFolder, CtrlCWhileWritingLeavesCompleteFilesAndASummarySayingCancelled) {
  json many = sample("block-indent-2d-50x30");  // 101 VTU files, 57 MB: about a second of writing
  many["analysis"] = {{"increments", 100}};
  many["output"] = {{"increments", "all"}};
  const std::string file = project_file(many, "sigint"), out = fs::path(file).parent_path() / "o";
  // stopped at once when the writing starts, then interrupted: the signal arrives while the first files are written
  const RunResult r = run_program_on_marker(ROLLSIM_BINARY, {"run", file, "--out", out}, "write results", [](int pid) {
    kill(pid, SIGSTOP);
    kill(pid, SIGINT);
    kill(pid, SIGCONT);
  });
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_TRUE(contains(r.err, "finishing the file being written")) << r.err;
  const json s = summary_in(out);
  EXPECT_EQ(s.value("status", ""), "cancelled");
  EXPECT_TRUE(contains(s.value("message", ""), "stopped by a signal while the results were written")) << s.dump(1);
  EXPECT_TRUE(contains(s.value("message", ""), "not written")) << s.dump(1);
  EXPECT_TRUE(temporaries(out).empty());
  const std::string pvd = read_text(out + "/results.pvd");  // when written: every file it lists exists
  for (size_t at = pvd.find("file=\""); at != std::string::npos; at = pvd.find("file=\"", at + 1)) {
    const std::string name = pvd.substr(at + 6, pvd.find('"', at + 6) - at - 6);
    EXPECT_TRUE(fs::exists(out + "/" + name)) << name;
  }
  fs::remove_all(fs::path(file).parent_path());
}

// Which run made the results: summary.json's `run` (start, end, the command, the project file's SHA-256).
TEST(RunFolder, TheSummarySaysWhichRunMadeIt) {
  const std::string file = project_file(sample("block-indent-2d-50x30"), "stamp"),
                    out = fs::path(file).parent_path() / "o";
  const RunResult r = run_rollsim({"run", file, "--out", out, "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json run = summary_in(out)["run"];
  const RunResult sum = run_program("/usr/bin/sha256sum", {file});
  EXPECT_EQ(run.value("project_sha256", ""), sum.out.substr(0, 64));
  EXPECT_TRUE(contains(run.value("command", ""), "run " + file + " --out " + out + " --quiet")) << run.dump(1);
  EXPECT_EQ(run.value("started", "").size(), 20u) << run.dump(1);  // 2026-11-28T11:30:26Z
  EXPECT_EQ(run.value("finished", "").size(), 20u) << run.dump(1);
  fs::remove_all(fs::path(file).parent_path());
}

}  // namespace test_run_folder
