#include "shading/fragment_capture.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/hdr_clamp.h"
#include "shading/scene_gpu.h"
#include "util/error.h"

#include <algorithm>
#include <cstring>

namespace rtlab {
namespace {

constexpr const char* kPass = "transparency.capture";
constexpr const char* kRowCounts = "transparency.capture_rows";
constexpr GLuint kRowCountsBinding = 0;  // shaders/shading/capture.frag
constexpr GLuint kFragmentsBinding = 1;
constexpr std::size_t kHeaderBytes = 16; // count, capacity, two pads
static_assert(sizeof(CapturedFragment) == 28, "CapturedFragment must match capture.frag's std430 layout");

// Bands of consecutive GL rows (bottom up) whose fragment counts fit `capacity` each.
std::vector<std::pair<int, int>> planBands(const std::vector<GLuint>& rowCounts, std::size_t capacity) {
  std::vector<std::pair<int, int>> bands;
  std::size_t inBand = 0;
  int first = 0;
  for (int row = 0; row < int(rowCounts.size()); ++row) {
    const std::size_t n = rowCounts[std::size_t(row)];
    if (n > capacity)
      throw Error(ExitCode::Internal, "fragment capture: row " + std::to_string(row) + " holds " + std::to_string(n) +
                                          " transparent fragments, more than a band of " + std::to_string(capacity));
    if (inBand + n > capacity) {
      bands.emplace_back(first, row);
      first = row;
      inBand = 0;
    }
    inBand += n;
  }
  if (inBand > 0) bands.emplace_back(first, int(rowCounts.size()));
  return bands;
}

} // namespace

std::string addFragmentCapturePass(FrameGraph& frame, CapturedFragments& out, std::size_t maxBytes) {
  const int width = frame.width(), height = frame.height();
  frame.addPass(kPass,
      [&](PassBuilder& b) {
        b.read(res::kDepth);
        b.writeBuffer(kRowCounts, {gl::BufferKind::Storage, std::size_t(height) * sizeof(GLuint)}, BufferBinding::Storage,
                      int(kRowCountsBinding));
      },
      [&out, width, height, maxBytes](PassContext& ctx) {
        out = CapturedFragments{};
        out.width = width;
        out.height = height;
        const gl::Framebuffer& fbo = ctx.framebuffer(kPass, {}, res::kDepth);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, width, height);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);

        // 1. Fragments per row.
        const gl::BufferObject& rows = ctx.buffer(kRowCounts);
        rows.clear();
        gl::Program& count = ctx.programs.get({{"shading/surface.vert", "shading/capture.frag"}, {"CAPTURE_COUNT"}, "capture.count"});
        count.set("uViewProj", ctx.view.viewProj);
        ctx.sceneGpu.draw(count, SceneGpu::Filter::Transparent, false);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        const std::vector<GLuint> rowCounts = rows.downloadAs<GLuint>();
        std::size_t total = 0;
        for (GLuint n : rowCounts) total += n;
        if (total == 0) return;

        // 2. Bands that fit the buffer, captured and read back one after the other.
        GLint blockLimit = 0;
        glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockLimit);
        const std::size_t limit = std::min(maxBytes, std::size_t(std::max(blockLimit, 0)));
        if (limit < kHeaderBytes + sizeof(CapturedFragment))
          throw Error(ExitCode::Internal, "fragment capture: storage blocks of " + std::to_string(limit) + " bytes are too small");
        const std::size_t capacity = (limit - kHeaderBytes) / sizeof(CapturedFragment);
        const auto bands = planBands(rowCounts, capacity);
        std::size_t largest = 0;
        for (const auto& [first, end] : bands) {
          std::size_t n = 0;
          for (int r = first; r < end; ++r) n += rowCounts[std::size_t(r)];
          largest = std::max(largest, n);
        }
        gl::BufferObject buffer({gl::BufferKind::Storage, kHeaderBytes + largest * sizeof(CapturedFragment)},
                                "transparency.capture_fragments");
        gl::Program& capture = ctx.programs.get({{"shading/surface.vert", "shading/capture.frag"}, {}, "capture"});
        setLayerUniforms(capture, ctx);
        capture.set("uHeight", height);
        out.fragments.reserve(total);
        glEnable(GL_SCISSOR_TEST);
        for (const auto& [first, end] : bands) {
          const GLuint header[4] = {0u, GLuint(largest), 0u, 0u};
          buffer.upload(header, sizeof(header));
          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFragmentsBinding, buffer.id());
          glScissor(0, first, width, end - first);
          capture.set("uFirstRow", first).set("uEndRow", end);
          ctx.sceneGpu.draw(capture, SceneGpu::Filter::Transparent, true);
          glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
          GLuint captured = 0;
          glGetNamedBufferSubData(buffer.id(), 0, sizeof(GLuint), &captured);
          std::size_t expected = 0;
          for (int r = first; r < end; ++r) expected += rowCounts[std::size_t(r)];
          if (captured != expected)
            throw Error(ExitCode::Internal, "fragment capture: rows " + std::to_string(first) + ".." + std::to_string(end) +
                                                " gave " + std::to_string(captured) + " fragments, the count pass " +
                                                std::to_string(expected));
          const std::size_t before = out.fragments.size();
          out.fragments.resize(before + captured);
          glGetNamedBufferSubData(buffer.id(), GLintptr(kHeaderBytes), GLsizeiptr(captured * sizeof(CapturedFragment)),
                                  out.fragments.data() + before);
          ++out.bands;
        }
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFragmentsBinding, 0);
      });
  return kRowCounts;
}

} // namespace rtlab
