#include "flowform/mesh/ReadOptions.hpp"

namespace flowform {

nlohmann::json toJson(const ReadOptions& opt) {
  nlohmann::json j = {{"path", opt.path},           {"isGeo", opt.isGeo},
                      {"cellType", static_cast<int>(opt.cellType)},
                      {"sizeFactor", opt.sizeFactor}, {"refinements", opt.refinements},
                      {"verbose", opt.verbose},       {"maxCells", opt.maxCells},
                      {"timeLimit", opt.timeLimit}};
  j["geoParameters"] = nlohmann::json::array();
  for (const auto& [name, value] : opt.geoParameters) j["geoParameters"].push_back({name, value});
  return j;
}

ReadOptions readOptionsFromJson(const nlohmann::json& j) {
  ReadOptions opt;
  opt.path = j.at("path").get<std::string>();
  opt.isGeo = j.at("isGeo").get<bool>();
  opt.cellType = static_cast<CellType>(j.at("cellType").get<int>());
  opt.sizeFactor = j.at("sizeFactor").get<double>();
  opt.refinements = j.at("refinements").get<int>();
  opt.verbose = j.at("verbose").get<bool>();
  opt.maxCells = j.at("maxCells").get<long long>();
  opt.timeLimit = j.at("timeLimit").get<double>();
  for (const auto& p : j.at("geoParameters"))
    opt.geoParameters.emplace_back(p.at(0).get<std::string>(), p.at(1).get<double>());
  return opt;
}

}  // namespace flowform
