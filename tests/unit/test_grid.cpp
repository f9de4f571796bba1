// The grid's chunks and the frustum test that culls them (common/grid.hpp, common/frustum.hpp):
// the chunks hold every triangle once, each inside its box; what the culling keeps is checked
// against the camera's geometry (behind, ahead, beside), and it only ever grows with the margin.
#include "common/frustum.hpp"
#include "common/grid.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

TEST(GridChunks, HoldEveryTriangleOnceInsideTheirBoxes) {
    const glm::vec2 size(90, 60);
    const int xq = 70, zq = 45;  // not multiples of the chunk size
    const auto positions = ocean::grid_positions(size, xq, zq);
    const ocean::GridTriangles t = ocean::grid_triangles(size, xq, zq);
    ASSERT_EQ(t.indices.size(), std::size_t(xq) * zq * 6);
    EXPECT_EQ(t.chunks.size(), std::size_t((xq + ocean::kChunkQuads - 1) / ocean::kChunkQuads) *
                                   std::size_t((zq + ocean::kChunkQuads - 1) / ocean::kChunkQuads));
    std::size_t next = 0;
    std::set<std::pair<unsigned, unsigned>> quads;  // (lowest index, highest) of each quad
    for (const ocean::GridChunk& c : t.chunks) {
        EXPECT_EQ(c.first, next);  // contiguous, in order: one multi-draw covers them all
        next = c.first + c.count;
        for (std::size_t i = c.first; i < c.first + c.count; ++i) {
            const glm::vec2 p = positions[t.indices[i]];
            EXPECT_TRUE(p.x >= c.lo.x - 1e-4f && p.x <= c.hi.x + 1e-4f && p.y >= c.lo.y - 1e-4f && p.y <= c.hi.y + 1e-4f)
                << "vertex " << t.indices[i] << " outside its chunk";
        }
        for (std::size_t i = c.first; i < c.first + c.count; i += 6)
            quads.insert({*std::min_element(&t.indices[i], &t.indices[i] + 6), *std::max_element(&t.indices[i], &t.indices[i] + 6)});
    }
    EXPECT_EQ(next, t.indices.size());
    EXPECT_EQ(quads.size(), std::size_t(xq) * zq) << "every quad exactly once";
}

TEST(GridChunks, TheWireframesEdgesOfAChunkAreAtTwiceItsTrianglesIndices) {
    // ES's wireframe (triangle_edges) draws a chunk's edges from 2 first, 2 count: each quad's
    // outline and diagonal, nothing from another chunk.
    const ocean::GridTriangles t = ocean::grid_triangles({40, 40}, 20, 20);
    const std::vector<unsigned> edges = ocean::triangle_edges(t.indices);
    ASSERT_EQ(edges.size(), 2 * t.indices.size());
    for (const ocean::GridChunk& c : t.chunks) {
        std::set<unsigned> triangle_vertices(t.indices.begin() + long(c.first), t.indices.begin() + long(c.first + c.count));
        std::set<unsigned> edge_vertices(edges.begin() + long(2 * c.first), edges.begin() + long(2 * (c.first + c.count)));
        EXPECT_EQ(edge_vertices, triangle_vertices);
    }
    // The first quad (a, c, b), (b, c, d): edges a-c, c-b, b-a, b-c, c-d, d-b.
    const unsigned a = 0, b = 1, c = 21, d = 22;
    EXPECT_EQ(std::vector<unsigned>(edges.begin(), edges.begin() + 12),
              (std::vector<unsigned>{a, c, c, b, b, a, b, c, c, d, d, b}));
}

TEST(Frustum, BoxesBehindBesideAndAhead) {
    // At the origin, 2 m up, looking along -z with a 60 degree field of view.
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 1000.0f) *
                         glm::lookAt(glm::vec3(0, 2, 0), glm::vec3(0, 2, -1), glm::vec3(0, 1, 0));
    const auto planes = ocean::frustum_planes(vp);
    EXPECT_FALSE(ocean::box_outside_frustum(planes, {-1, -1, -20}, {1, 1, -10}));     // ahead
    EXPECT_TRUE(ocean::box_outside_frustum(planes, {-1, -1, 10}, {1, 1, 20}));        // behind
    EXPECT_TRUE(ocean::box_outside_frustum(planes, {100, -1, -20}, {120, 1, -10}));   // far to the right
    EXPECT_FALSE(ocean::box_outside_frustum(planes, {-5, -1, -5}, {5, 1, 5}));        // around the eye
    EXPECT_TRUE(ocean::box_outside_frustum(planes, {-1, -1, -1200}, {1, 1, -1100}));  // past the far plane
}

TEST(GridChunks, CullingKeepsWhatTheCameraCanSeeAndGrowsWithTheMargin) {
    const ocean::GridTriangles t = ocean::grid_triangles({800, 800}, 400, 400);
    const glm::mat4 vp = glm::perspective(glm::radians(50.0f), 16.0f / 9.0f, 0.1f, 2000.0f) *
                         glm::lookAt(glm::vec3(0, 12, 0), glm::vec3(0, 0, -50), glm::vec3(0, 1, 0));
    const auto kept = ocean::visible_chunks(t.chunks, vp, 0);
    auto has = [&](glm::vec2 p) {
        for (std::size_t c : kept)
            if (p.x >= t.chunks[c].lo.x && p.x <= t.chunks[c].hi.x && p.y >= t.chunks[c].lo.y && p.y <= t.chunks[c].hi.y)
                return true;
        return false;
    };
    EXPECT_TRUE(has({0, -50}));    // the point looked at
    EXPECT_TRUE(has({0, -390}));   // towards the horizon, straight ahead
    EXPECT_FALSE(has({0, 300}));   // behind
    EXPECT_FALSE(has({-390, 0}));  // beside, out of the field of view
    EXPECT_LT(kept.size(), t.chunks.size() / 2) << "a view sees a wedge of the plane";
    std::size_t previous = kept.size();
    for (float margin : {5.0f, 20.0f, 100.0f}) {
        const std::size_t n = ocean::visible_chunks(t.chunks, vp, margin).size();
        EXPECT_GE(n, previous) << "margin " << margin;
        previous = n;
    }
}

}  // namespace
