#include "app/toml_table.h"

#include <cmath>
#include <filesystem>
#include <limits>

#include "engine/input_error.h"

namespace mtcut::app {
namespace {

std::string location(const std::string& file, const toml::source_region& region) {
  return region.begin.line > 0 ? file + ":" + std::to_string(region.begin.line) : file;
}

const char* type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date or time";
  }
}

}  // namespace

toml::table parse_toml_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw engine::InputError(path + ": no such file");
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw engine::InputError(location(path, e.source()) + ": " + std::string(e.description()));
  }
}

TomlTable::TomlTable(const toml::table& table, std::string file, std::string where)
    : table_(&table), file_(std::move(file)), where_(std::move(where)) {}

std::string TomlTable::qualified(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }

void TomlTable::fail(const toml::node* at, const std::string& what) const {
  throw engine::InputError(location(file_, at ? at->source() : table_->source()) + ": " + what);
}

const toml::node* TomlTable::take(const std::string& key) {
  const toml::node* node = table_->get(key);
  if (node) used_.insert(key);
  return node;
}

const toml::node* TomlTable::node(const std::string& key) { return take(key); }

std::optional<double> TomlTable::number(const std::string& key) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  if (!n->is_number()) fail(n, "'" + qualified(key) + "' must be a number, not " + type_name(*n));
  const double value = n->value<double>().value();
  if (!std::isfinite(value)) fail(n, "'" + qualified(key) + "' must be finite");
  return value;
}

std::optional<std::int64_t> TomlTable::integer(const std::string& key) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  if (!n->is_integer()) fail(n, "'" + qualified(key) + "' must be an integer, not " + type_name(*n));
  return n->value<std::int64_t>().value();
}

std::optional<bool> TomlTable::boolean(const std::string& key) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  if (!n->is_boolean()) fail(n, "'" + qualified(key) + "' must be true or false, not " + type_name(*n));
  return n->value<bool>().value();
}

std::optional<std::string> TomlTable::string(const std::string& key) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  if (!n->is_string()) fail(n, "'" + qualified(key) + "' must be a string, not " + type_name(*n));
  return n->value<std::string>().value();
}

std::optional<engine::Vec3> TomlTable::vec3(const std::string& key) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 3) fail(n, "'" + qualified(key) + "' must be an array of three numbers");
  engine::Vec3 v;
  for (int k = 0; k < 3; ++k) {
    const toml::node& item = *a->get(static_cast<std::size_t>(k));
    if (!item.is_number()) fail(&item, "'" + qualified(key) + "' must be an array of three numbers");
    v[k] = item.value<double>().value();
  }
  if (!v.allFinite()) fail(n, "'" + qualified(key) + "' must be finite");
  return v;
}

std::optional<TomlTable> TomlTable::table(const std::string& key) {
  const toml::node* n = take(key);
  if (!n) return std::nullopt;
  if (!n->is_table()) fail(n, "'" + qualified(key) + "' must be a table, not " + type_name(*n));
  return TomlTable(*n->as_table(), file_, qualified(key));
}

std::vector<TomlTable> TomlTable::tables(const std::string& key) {
  std::vector<TomlTable> out;
  const toml::node* n = take(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    fail(n, "'" + qualified(key) + "' must be an array of tables ([[" + qualified(key) + "]])");
  for (std::size_t i = 0; i < a->size(); ++i)
    out.emplace_back(*a->get(i)->as_table(), file_, qualified(key) + "[" + std::to_string(i) + "]");
  return out;
}

void TomlTable::read(const std::string& key, double& out) {
  if (auto v = number(key)) out = *v;
}
void TomlTable::read(const std::string& key, int& out) {
  if (auto v = integer(key)) {
    if (*v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
      fail(take(key), "'" + qualified(key) + "' is out of range");
    out = static_cast<int>(*v);
  }
}
void TomlTable::read(const std::string& key, bool& out) {
  if (auto v = boolean(key)) out = *v;
}
void TomlTable::read(const std::string& key, std::string& out) {
  if (auto v = string(key)) out = *v;
}
void TomlTable::read(const std::string& key, engine::Vec3& out) {
  if (auto v = vec3(key)) out = *v;
}

void TomlTable::finish() const {
  for (const auto& [key, node] : *table_)
    if (!used_.count(std::string(key.str())))
      fail(&node, "unknown key '" + qualified(std::string(key.str())) + "'");
}

}  // namespace mtcut::app
