// `pcsg figures`: the bounded queue and the generator's event stream between threads (no
// event lost, order kept, producers released when the consumer stops), and end-to-end runs of
// the binary on stored graphs (tests/data/graphs), which keep them to a few seconds.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>

#include "app/render/graph_event_stream.h"
#include "render/image.h"
#include "run_pcsg.h"

namespace pcsg::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(BoundedQueueTest, KeepsOrderAndCapacity) {
  BoundedQueue<int> q(3);
  constexpr int kItems = 1000;
  std::thread producer([&] {
    for (int i = 0; i < kItems; ++i) ASSERT_TRUE(q.push(i));
    q.close();
  });
  int expected = 0;
  while (std::optional<int> v = q.pop()) {
    EXPECT_EQ(*v, expected++);
    if (expected % 100 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  producer.join();
  EXPECT_EQ(expected, kItems) << "every item arrives";
  EXPECT_LE(q.high_water(), q.capacity());
}

TEST(BoundedQueueTest, CloseReleasesABlockedProducerAndDrains) {
  BoundedQueue<int> q(1);
  ASSERT_TRUE(q.push(1));
  bool second = true;
  std::thread producer([&] { second = q.push(2); });  // blocks: the queue is full
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  q.close();
  producer.join();
  EXPECT_FALSE(second) << "a push into a closed queue fails";
  EXPECT_EQ(q.pop(), std::optional<int>(1)) << "what was queued is still delivered";
  EXPECT_EQ(q.pop(), std::nullopt);
}

// The generator's listener calls, made from a worker thread as generate_graph makes them,
// reach a slow consumer complete and in order.
TEST(GraphEventStreamTest, SlowConsumerLosesNothing) {
  constexpr int kStates = 40, kCandidatesPerState = 3;
  BoundedQueue<GraphEvent> q(4);
  std::atomic<bool> cancel{false};
  std::thread generator([&] {
    GraphEventStream stream(q, cancel);
    StateGraph g;
    for (int i = 0; i < kStates; ++i) {
      State s;
      s.id = i;
      g.states.push_back(s);
      stream.on_state(g, g.states.back());
      for (int k = 0; k < kCandidatesPerState; ++k) {
        Candidate c;
        c.from = i;
        c.steps = k;
        stream.on_candidate(g, c);
        stream.on_progress(g, i, k + 1, kCandidatesPerState);
      }
    }
    stream.push(GraphFinished{g});
    q.close();
  });
  int states = 0, candidates = 0, progress = 0;
  bool finished = false;
  while (std::optional<GraphEvent> e = q.pop()) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));  // slower than the producer
    if (auto* s = std::get_if<StateFound>(&*e)) {
      EXPECT_EQ(s->state.id, states++);
    }
    if (auto* c = std::get_if<CandidateTried>(&*e)) {
      EXPECT_EQ(c->index, candidates);
      EXPECT_EQ(c->from.id, candidates / kCandidatesPerState) << "the start state is attached";
      EXPECT_EQ(c->candidate.steps, candidates % kCandidatesPerState);
      ++candidates;
    }
    if (std::get_if<GenerationProgress>(&*e)) ++progress;
    if (auto* f = std::get_if<GraphFinished>(&*e)) {
      finished = true;
      EXPECT_EQ(f->graph.states.size(), static_cast<std::size_t>(kStates));
    }
  }
  generator.join();
  EXPECT_EQ(states, kStates);
  EXPECT_EQ(candidates, kStates * kCandidatesPerState);
  EXPECT_EQ(progress, kStates * kCandidatesPerState);
  EXPECT_TRUE(finished);
  EXPECT_FALSE(cancel);
  EXPECT_LE(q.high_water(), q.capacity());
}

TEST(GraphEventStreamTest, AStoppedConsumerCancelsTheGenerator) {
  BoundedQueue<GraphEvent> q(2);
  std::atomic<bool> cancel{false};
  std::thread generator([&] {
    GraphEventStream stream(q, cancel);
    StateGraph g;
    g.states.resize(1);
    while (!cancel) stream.on_progress(g, 0, 0, 0);  // as generate_graph checks its flag
  });
  ASSERT_TRUE(q.pop().has_value());
  q.close();  // the consumer gives up
  generator.join();
  EXPECT_TRUE(cancel);
}

using pcsg::testing::ExeRun;
// Runs pcsg with stderr merged into what is captured.
ExeRun run_pcsg(const std::string& args) { return pcsg::testing::run_pcsg(args, true); }

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("pcsg_figures_test_" + name);
  fs::remove_all(d);
  return d;
}

#if PCSG_WITH_RENDER

std::string source(const std::string& relative) {
  return std::string(PCSG_SOURCE_DIR) + "/" + relative;
}

// The failed candidate of the stored Example 2 graph whose motion collides soonest.
int cheapest_collision(const json& graph) {
  int best = -1;
  std::pair<int, int> cost{1 << 30, 0};
  for (std::size_t i = 0; i < graph["candidates"].size(); ++i) {
    const json& c = graph["candidates"][i];
    const std::string reason = c.value("reason", std::string());
    const std::string motion = c["motion"].get<std::string>();
    const std::size_t at = reason.rfind(motion + ":");
    if (c["feasible"].get<bool>() || at == std::string::npos ||
        reason.find("collision", at) == std::string::npos)
      continue;
    const std::pair<int, int> k{c["attempts"].get<int>(), c["steps"].get<int>()};
    if (k < cost) cost = k, best = static_cast<int>(i);
  }
  return best;
}

// The transition folders drawn into a scene's output folder.
std::vector<fs::path> transition_folders(const fs::path& scene_out) {
  std::vector<fs::path> folders;
  const fs::path transitions = scene_out / "transitions";
  if (fs::is_directory(transitions))
    for (const auto& f : fs::directory_iterator(transitions)) folders.push_back(f.path());
  return folders;
}

TEST(FiguresCommandTest, FailedCandidateSequenceEndsAtTheCollision) {
  std::ifstream in(source("tests/data/graphs/example2.json"));
  const json graph = json::parse(in);
  const int k = cheapest_collision(graph);
  ASSERT_GE(k, 0);
  const fs::path out = fresh_dir("collision");
  const ExeRun r = run_pcsg("figures -q --scene " + source("scenes/example2.yaml") + " --graph " +
                            source("tests/data/graphs/example2.json") +
                            " --only transitions --stride 1 --candidate " + std::to_string(k) +
                            " --size 320x240 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("drew 1 transitions"), std::string::npos) << r.out;
  const std::vector<fs::path> folders = transition_folders(out / "example2");
  ASSERT_EQ(folders.size(), 1u);
  std::ifstream fin(folders[0] / "frames.json");
  const json frames = json::parse(fin);
  ASSERT_FALSE(frames["frames"].empty());
  const json& last = frames["frames"].back();
  EXPECT_EQ(last["phase"], "collision") << "the sequence ends at the collision";
  EXPECT_FALSE(last["collided_a"].empty());
  EXPECT_FALSE(last["collided_b"].empty());
  EXPECT_FALSE(frames["feasible"].get<bool>());
  // with --stride 1 every replayed frame is drawn: one PNG per frame, and the sheet
  std::size_t pngs = 0;
  for (const auto& f : fs::directory_iterator(folders[0]))
    pngs += f.path().filename().string().rfind("frame-", 0) == 0;
  EXPECT_EQ(pngs, frames["frames"].size());
  EXPECT_TRUE(fs::exists(folders[0] / "contact_sheet.png"));
}

TEST(FiguresCommandTest, DiagramOnlyFromAStoredGraph) {
  const fs::path out = fresh_dir("diagram");
  const ExeRun r = run_pcsg("figures -q --scene " + source("scenes/example1.yaml") + " --graph " +
                            source("tests/data/graphs/example1.json") + " --only diagram --out " +
                            out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const fs::path d = out / "example1";
  EXPECT_TRUE(fs::exists(d / "diagram.png"));
  EXPECT_TRUE(fs::exists(d / "diagram.dot"));
  EXPECT_TRUE(fs::exists(d / "graph.json"));
  EXPECT_TRUE(fs::exists(d / "graph.dot"));
  EXPECT_TRUE(fs::exists(out / "fig6.png")) << "Example 1's diagram is the paper's Fig. 6";
  EXPECT_FALSE(fs::exists(d / "transitions"));
  EXPECT_FALSE(fs::exists(d / "apart.png"));
}

// A candidate toward a rim-crossing CF fails when its motion arrives with the other crossing
// sign (reaches_target); its sequence says so, as the generation did. The stored graph is
// Example 2's (session 18's main command) with one such candidate kept: from state 4 toward
// {(eA-e1, 1)} with the crossing "eA-e1 +", its slidingB+rotation arrives with "eA-e1 -".
// (Until session 19 the header and frames.json called that replay "feasible".)
TEST(FiguresCommandTest, ArrivalWithTheOtherCrossingIsAFailure) {
  const fs::path out = fresh_dir("other_crossing");
  const ExeRun r = run_pcsg(
      "figures -q --scene " + source("scenes/example2.yaml") + " --graph " +
      source("tests/data/graphs/example2_other_crossing.json") +
      " --only transitions --candidate 0 --max-frames 2 --size 160x120 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("replay differs"), std::string::npos) << r.out;
  const std::vector<fs::path> folders = transition_folders(out / "example2");
  ASSERT_EQ(folders.size(), 1u);
  std::ifstream fin(folders[0] / "frames.json");
  const json frames = json::parse(fin);
  EXPECT_FALSE(frames["feasible"].get<bool>());
  const std::string reason = frames["reason"].get<std::string>();
  EXPECT_NE(reason.find("arrives with the crossing eA-e1 -, not eA-e1 +"), std::string::npos)
      << reason;
  // Its last frame carries the failure banner, as a collision frame does (until session 20
  // only collision frames had it, and this one said "done" under a "reached" ring): a band in
  // the warning colour across the frame between the header and the view, which the first
  // frame lacks.
  std::vector<fs::path> pngs;
  for (const auto& f : fs::directory_iterator(folders[0]))
    if (f.path().filename().string().rfind("frame-", 0) == 0) pngs.push_back(f.path());
  std::sort(pngs.begin(), pngs.end());
  ASSERT_GE(pngs.size(), 2u);
  auto banner_rows = [](const render::Image& im) {
    auto warning = [](const std::uint8_t* p) {  // palette::kWarning = (0.86, 0.12, 0.10)
      return p[0] > 170 && p[0] - p[1] > 80 && p[0] - p[2] > 80;
    };
    int rows = 0;
    for (int y = 0; y < im.height; ++y)
      rows += warning(im.pixel(1, y)) && warning(im.pixel(im.width / 2, y)) &&
              warning(im.pixel(im.width - 2, y));
    return rows;
  };
  const render::Image first = render::read_png(pngs.front().string());
  const render::Image last = render::read_png(pngs.back().string());
  EXPECT_EQ(banner_rows(first), 0) << pngs.front();
  EXPECT_GT(banner_rows(last), 5) << pngs.back();
  EXPECT_GT(last.height, first.height) << "the banner adds a band above the view";
}

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The torus's states and transitions drawn while its graph streams, in one run (the one small
// scene that merges states; its generation is most of the two tests below, ~375 s each on a
// slow 2-core machine when each ran its own): both tests read it, and run in one process (the
// CTest group FiguresCommandTest.FinalNumbering).
const std::string kTorusStates = " --only states --thumb 96x72";
const std::string kTorusTransitions = " --only transitions --size 160x120 --max-frames 3";
struct LiveTorus {
  fs::path dir;
  ExeRun run;
};
const LiveTorus& live_torus() {
  static const LiveTorus live = [] {
    LiveTorus l{fresh_dir("renumbered_live"), {}};
    l.run = run_pcsg("figures -q --scene " + source("scenes/torus.yaml") + kTorusStates +
                     kTorusTransitions + " --out " + l.dir.string());
    return l;
  }();
  return live;
}

// The torus scene's run finds 13 states and proves two of them one region (the generator
// merges and renumbers them when it ends): every states/state-NN.png must show the final
// graph's state NN, the same picture as one drawn from the written graph.json, and no picture
// of a merged-away id may stay. (Before session 7 the pictures kept their streaming ids:
// Example 2's state-37.png showed {(eA-e1, 1), (fA1-e1, 1), (fA1-f1, 1)} while graph.json's
// state 37 is {(fA2-e1, 2), (fA2-f1, 1)}.)
TEST(FiguresCommandTest, StatePicturesFollowTheFinalNumbering) {
  const fs::path live = live_torus().dir, stored = fresh_dir("renumbered_stored");
  const ExeRun& r = live_torus().run;
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const fs::path graph = live / "torus" / "graph.json";
  std::ifstream in(graph);
  const std::size_t states = json::parse(in)["states"].size();
  const ExeRun again = run_pcsg("figures -q --scene " + source("scenes/torus.yaml") + " --graph " +
                                graph.string() + kTorusStates + " --out " + stored.string());
  ASSERT_EQ(again.exit_code, 0) << again.out;
  std::size_t pictures = 0;
  for (const auto& f : fs::directory_iterator(live / "torus" / "states")) {
    ++pictures;
    const bool same =
        file_bytes(f.path()) == file_bytes(stored / "torus" / "states" / f.path().filename());
    EXPECT_TRUE(same) << f.path().filename() << " differs from the stored graph's picture";
  }
  EXPECT_EQ(pictures, states);
}

// The same for the transitions: a folder drawn while the graph streamed carries the streaming
// id of its start state ("N-<target CF>") in its name, its frames' headers, its contact sheet
// and frames.json; after the final merge each must carry the final ids, exactly as a drawing
// of the written graph.json does. (Before session 8 they kept the streaming ids: the torus's
// 13 states merge into 12.) The live drawing is live_torus()'s; the stored ones are two
// drawings of its candidates' motions, small and with few frames.
TEST(FiguresCommandTest, TransitionsFollowTheFinalNumbering) {
  const fs::path live = live_torus().dir, stored = fresh_dir("renumbered_tr_stored");
  const std::string common =
      " -q --scene " + source("scenes/torus.yaml") + kTorusTransitions + " --out ";
  const ExeRun& r = live_torus().run;
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // Every replay ends as the generation's motion did (until the candidates named their motion,
  // Candidate::run, one feasible candidate of the torus replayed into a collision).
  EXPECT_EQ(r.out.find("replay differs"), std::string::npos) << r.out;
  const fs::path graph = live / "torus" / "graph.json";
  // an older run's transition in the folder drawn into: a drawing of every candidate removes it
  const fs::path stale = stored / "torus" / "transitions" / "99-fA-f1x1";
  fs::create_directories(stale);
  std::ofstream(stale / "frames.json") << "{}";
  const ExeRun again = run_pcsg("figures --graph " + graph.string() + common + stored.string());
  ASSERT_EQ(again.exit_code, 0) << again.out;
  EXPECT_EQ(again.out.find("replay differs"), std::string::npos) << again.out;
  EXPECT_FALSE(fs::exists(stale)) << "an older run's transition folder is kept";
  std::set<std::string> folders, want;
  for (const auto& d : fs::directory_iterator(live / "torus" / "transitions")) {
    folders.insert(d.path().filename().string());
    std::ifstream fj(d.path() / "frames.json");
    const json frames = json::parse(fj);
    const std::string name = d.path().filename().string();
    EXPECT_EQ(name.substr(0, name.find('-')), std::to_string(frames["from"].get<int>()));
    for (const auto& f : fs::directory_iterator(d.path())) {
      const fs::path twin = stored / "torus" / "transitions" / name / f.path().filename();
      EXPECT_TRUE(file_bytes(f.path()) == file_bytes(twin))
          << name << "/" << f.path().filename().string() << " differs from the stored graph's";
    }
  }
  for (const auto& d : fs::directory_iterator(stored / "torus" / "transitions"))
    want.insert(d.path().filename().string());
  EXPECT_EQ(folders, want);
  EXPECT_FALSE(folders.empty());

  // drawing some candidates only (--candidate) leaves the other candidates' folders alone
  const ExeRun one =
      run_pcsg("figures --graph " + graph.string() + common + stored.string() + " --candidate 0");
  ASSERT_EQ(one.exit_code, 0) << one.out;
  std::set<std::string> after;
  for (const auto& d : fs::directory_iterator(stored / "torus" / "transitions"))
    after.insert(d.path().filename().string());
  EXPECT_EQ(after, want);
}

TEST(FiguresCommandTest, RejectsUnknownParts) {
  const ExeRun r = run_pcsg("figures --only pictures --out " + fresh_dir("bad").string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("--only pictures"), std::string::npos) << r.out;
}

#else

TEST(FiguresCommandTest, SaysItWasBuiltWithoutTheRenderer) {
  const ExeRun r = run_pcsg("figures --out " + fresh_dir("norender").string());
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("without the renderer"), std::string::npos) << r.out;
}

#endif

}  // namespace
}  // namespace pcsg::app
