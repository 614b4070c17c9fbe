// matchcast-feeder LOG [--port N] [--host H] [--speed X] [--loop] [--no-wait]
#include <boost/program_options.hpp>

#include <csignal>
#include <iostream>

#include "server/tools/feeder/feeder.hpp"

namespace {
mc::feeder::Feeder* g_feeder = nullptr;
extern "C" void on_signal(int) {
  if (g_feeder) g_feeder->stop();
}
}  // namespace

int main(int argc, char** argv) {
  namespace po = boost::program_options;
  mc::feeder::FeederConfig cfg;
  po::options_description opts("matchcast-feeder: replay a game log as a live rcssserver monitor port");
  opts.add_options()("help,h", "show this help")(
      "log", po::value(&cfg.log_path)->required(), "game log (.rcg, .rcg.gz; any version)")(
      "port,p", po::value(&cfg.port)->default_value(6000), "UDP port for (dispinit); 0 = ephemeral, printed")(
      "host", po::value(&cfg.bind_host)->default_value("127.0.0.1"), "address to bind")(
      "speed,s", po::value(&cfg.speed)->default_value(1.0), "replay speed factor (2 = twice real time)")(
      "loop,l", po::bool_switch(&cfg.loop), "start the log over when it ends")(
      "no-wait", "start the replay at once instead of when the first monitor connects");
  po::positional_options_description pos;
  pos.add("log", 1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(opts).positional(pos).run(), vm);
    if (vm.count("help")) {
      std::cout << opts << "\n";
      return 0;
    }
    po::notify(vm);
  } catch (const std::exception& e) {
    std::cerr << "matchcast-feeder: " << e.what() << "\n" << opts << "\n";
    return 2;
  }
  cfg.wait_for_monitor = vm.count("no-wait") == 0;
  mc::feeder::Feeder feeder(cfg);
  std::string error;
  if (!feeder.open(error)) {
    std::cerr << "matchcast-feeder: " << error << "\n";
    return 1;
  }
  g_feeder = &feeder;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  // Scripts parse this line to find an ephemeral port.
  std::cout << "matchcast-feeder: listening on " << cfg.bind_host << ":" << feeder.port() << std::endl;
  if (!feeder.run(error)) {
    std::cerr << "matchcast-feeder: " << error << "\n";
    return 1;
  }
  std::cout << "matchcast-feeder: sent " << feeder.shows_sent() << " shows" << std::endl;
  return 0;
}
