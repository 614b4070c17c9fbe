#include "wasm/log_reference.hpp"

#include "server/ingest/state_source.hpp"

namespace mc::wasm {

bool broadcast_log_file(const std::string& path, const LogSessionOptions& options, std::string& out,
                        std::string& error) {
  auto source = ingest::open_log(path, error);
  if (!source) return false;
  WorldState state;
  if (!source->next(state)) {
    error = path + ": no game states";
    return false;
  }
  put_record(out, 'h', app::make_hello(state, source->params(), options.pipeline.keyframe_interval, options.match_id));
  app::BroadcastPipeline pipeline(source->params(), options.pipeline);
  struct Sink : app::PipelineSink {
    std::string& out;
    explicit Sink(std::string& o) : out(o) {}
    void control(std::string json) override { put_record(out, 'c', json); }
    void frame(std::string bytes, bool key) override { put_record(out, key ? 'k' : 'f', bytes); }
  } sink(out);
  const std::uint64_t base = options.server_time_base_ms;
  auto stamp = [base](std::uint32_t seq) { return base + std::uint64_t{seq} * 50; };
  std::uint64_t states = 0;
  do {
    pipeline.push(state);
    pipeline.emit_all(stamp, sink);
  } while (++states < options.max_states && source->next(state));
  pipeline.finish();
  pipeline.emit_all(stamp, sink);
  return true;
}

}  // namespace mc::wasm
