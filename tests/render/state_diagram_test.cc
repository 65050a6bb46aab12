// The graph diagram (paper Fig. 6) of Example 1, drawn from the graph stored in
// tests/data/graphs/example1.json (generated once with `pcsg generate`, so that this image
// does not follow the generator's changes), and the dot layout's rows.
#include "render/state_diagram.h"

#include <gtest/gtest.h>

#include "engine/scene/scene.h"
#include "render/graph_json_reader.h"
#include "render/graph_layout.h"
#include "tests/render/golden.h"

namespace pcsg::render {
namespace {

SceneGeometry example(int n) {
  return build_scene_geometry(load_scene_file(std::string(PCSG_SOURCE_DIR) + "/scenes/example" +
                                              std::to_string(n) + ".yaml"));
}

TEST(StateDiagramTest, Example1LnGraph) {
  PCSG_SKIP_WITHOUT_LABEL_FONT();
  const SceneGeometry scene = example(1);
  const StateGraph graph =
      read_graph_json(std::string(PCSG_SOURCE_DIR) + "/tests/data/graphs/example1.json", scene);
  ASSERT_EQ(graph.states.size(), 6u);
  const std::vector<Image> pictures = draw_state_thumbnails(scene, graph.states, {});
  ASSERT_EQ(pictures.size(), 6u);
  for (const Image& p : pictures) {
    EXPECT_EQ(p.width, pictures[0].width) << "framed and cropped alike";
    EXPECT_EQ(p.height, pictures[0].height);
  }
  TextPainter text;
  const Diagram d = draw_state_diagram(graph, scene, pictures, StateDiagramOptions{}, text);
  EXPECT_NE(d.dot.find("pos="), std::string::npos) << "the layout's dot carries positions";
  testing::expect_matches_golden(d.image, "example1_diagram");
}

// Example 2's stored graph (27 states, 75 links): many links within rows, which Graphviz 2.43
// cannot label without corrupting its memory, and too many pairs to label at all: the diagram
// is drawn compact, and stays a few screens wide.
TEST(StateDiagramTest, LargeGraphIsCompactAndLaysOut) {
  const SceneGeometry scene = example(2);
  const StateGraph graph =
      read_graph_json(std::string(PCSG_SOURCE_DIR) + "/tests/data/graphs/example2.json", scene);
  const std::vector<Image> pictures(graph.states.size(), Image(120, 100));
  TextPainter text;
  const Diagram d = draw_state_diagram(graph, scene, pictures, StateDiagramOptions{}, text);
  EXPECT_LT(d.image.width, 4000);
  EXPECT_EQ(d.dot.find("label=<"), std::string::npos) << "no link labels when compact";
}

TEST(StateDiagramTest, PicturesMustMatchTheStates) {
  const SceneGeometry scene = example(1);
  StateGraph graph;
  graph.states.resize(2);
  TextPainter text;
  EXPECT_THROW(draw_state_diagram(graph, scene, {Image(8, 8)}, {}, text), Error);
}

TEST(GraphLayoutTest, RowsAndLabelsOfFlatEdges) {
  // a seed on top, three states of one row below, one more below them and one alone at the
  // bottom (no edge reaches it: the row order alone puts it there)
  const std::vector<LayoutNode> nodes = {{100, 80, 0}, {100, 80, 1}, {100, 80, 1},
                                         {100, 80, 1}, {100, 80, 2}, {100, 80, 3}};
  // labels on an edge between rows and on an edge within a row (a "flat" edge, whose label
  // Graphviz 2.43 cannot place without corrupting its memory)
  const std::vector<LayoutEdge> edges = {{0, 1}, {0, 2}, {1, 2, 60, 14}, {2, 3}, {3, 4},
                                         {0, 3, 60, 14}};
  const GraphLayout l = layout_graph(nodes, edges);
  ASSERT_EQ(l.centres.size(), 6u);
  EXPECT_LT(l.centres[0].y(), l.centres[1].y());
  EXPECT_DOUBLE_EQ(l.centres[1].y(), l.centres[2].y());
  EXPECT_DOUBLE_EQ(l.centres[1].y(), l.centres[3].y());
  EXPECT_LT(l.centres[3].y(), l.centres[4].y());
  EXPECT_LT(l.centres[4].y(), l.centres[5].y());
  // splines run from `from` to `to` and end on the boxes (half a box from the centres)
  for (std::size_t k = 0; k < edges.size(); ++k) {
    ASSERT_GE(l.splines[k].size(), 4u);
    const Eigen::Vector2d a = l.centres[edges[k].from], b = l.centres[edges[k].to];
    EXPECT_LT((l.splines[k].front() - a).norm(), (l.splines[k].front() - b).norm()) << k;
    EXPECT_LT((l.splines[k].back() - b).norm(), 80) << k;
  }
  EXPECT_GT(l.label_centres[5].norm(), 0) << "the labelled edge has its label placed";
  // the flat edge's label sits between its ends, in their row
  EXPECT_DOUBLE_EQ(l.label_centres[2].y(), l.centres[1].y());
  EXPECT_GT(l.label_centres[2].x(), std::min(l.centres[1].x(), l.centres[2].x()));
  EXPECT_LT(l.label_centres[2].x(), std::max(l.centres[1].x(), l.centres[2].x()));
  EXPECT_THROW(layout_graph(nodes, {{0, 7}}), Error);
}

}  // namespace
}  // namespace pcsg::render
