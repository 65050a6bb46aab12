// graph.json read back (render/graph_json_reader.h): what `pcsg figures` and the viewer replay
// from a stored graph must survive the round trip, the start witness of a retried candidate
// (Candidate::start) and which motion a candidate reports (Candidate::run) included.
#include "render/graph_json_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "engine/generator/graph_io.h"
#include "engine/scene/scene.h"

namespace pcsg::render {
namespace {

TEST(GraphJsonReaderTest, CandidateStartWitnessSurvivesTheRoundTrip) {
  const SceneGeometry scene =
      build_scene_geometry(load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example1.yaml"));
  StateGraph g;
  g.scene = "round trip";
  State s;
  s.id = 0;
  g.states.push_back(s);
  Candidate own, retried;
  own.from = retried.from = 0;
  retried.start = Pose{};
  retried.start->position = {0.25, -1.5, 3.0};
  retried.start->quaternion =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  retried.run = {2, 1, 4};
  g.candidates = {own, retried};
  const std::string path = ::testing::TempDir() + "/graph_round_trip.json";
  std::ofstream(path) << graph_to_json(g, scene);
  const StateGraph back = read_graph_json(path, scene);
  std::remove(path.c_str());
  ASSERT_EQ(back.candidates.size(), 2u);
  EXPECT_FALSE(back.candidates[0].start) << "the state's own witness: no start written";
  ASSERT_TRUE(back.candidates[1].start);
  // 17 significant digits: the pose comes back to the last bits
  EXPECT_LT((back.candidates[1].start->position - retried.start->position).norm(), 1e-15);
  EXPECT_LT(back.candidates[1].start->quaternion.angularDistance(retried.start->quaternion), 1e-15);
  EXPECT_FALSE(back.candidates[0].run.known()) << "no motion tried: no run written";
  EXPECT_EQ(back.candidates[1].run.start, 2);
  EXPECT_EQ(back.candidates[1].run.plan, 1);
  EXPECT_EQ(back.candidates[1].run.variant, 4);
}

}  // namespace
}  // namespace pcsg::render
