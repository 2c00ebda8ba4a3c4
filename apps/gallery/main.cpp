// casteljau-gallery OUTDIR: computes every figure and writes OUTDIR/index.html.
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "figures.hpp"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  using casteljau::gallery::Figure;
  if (argc != 2) {
    std::cerr << "usage: casteljau-gallery OUTDIR  (writes OUTDIR/index.html)\n";
    return 2;
  }
  std::vector<Figure> figures;
  std::size_t index = 0;
  try {
    for (const auto& make : casteljau::gallery::figure_list()) {
      ++index;
      figures.push_back(make());
    }
  } catch (const std::exception& e) {
    std::cerr << "casteljau-gallery: figure " << index << ": " << e.what() << '\n';
    return 1;
  }
  const std::string page = casteljau::gallery::html_page(figures);
  const fs::path dir(argv[1]);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    std::cerr << "casteljau-gallery: cannot create " << dir << ": " << ec.message() << '\n';
    return 1;
  }
  // Written next to the target and renamed, so that a reader never sees half a page.
  const fs::path tmp = dir / "index.html.tmp", out = dir / "index.html";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << page;
    f.close();
    if (!f) {
      std::cerr << "casteljau-gallery: cannot write " << tmp << '\n';
      return 1;
    }
  }
  fs::rename(tmp, out, ec);
  if (ec) {
    std::cerr << "casteljau-gallery: cannot write " << out << ": " << ec.message() << '\n';
    return 1;
  }
  return 0;
}
