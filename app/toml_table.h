#pragma once
// A strict view of a TOML table for our config files: each key read is
// recorded, and finish() rejects every key that was not read. Every fault is
// one InputError line "file:line: what", so a typo in a scenario or preset
// never passes silently.

#include <optional>
#include <string>
#include <toml++/toml.h>
#include <unordered_set>
#include <vector>

#include "engine/predicates.h"

namespace mtcut::app {

// Parses a TOML file; throws InputError "file:line: ..." on a syntax error,
// or when the file is missing.
toml::table parse_toml_file(const std::string& path);

class TomlTable {
 public:
  // `where` names the table in messages ("" for the top level).
  TomlTable(const toml::table& table, std::string file, std::string where = "");

  // Value getters: nullopt when the key is absent; InputError when the type is wrong.
  std::optional<double> number(const std::string& key);
  std::optional<std::int64_t> integer(const std::string& key);
  std::optional<bool> boolean(const std::string& key);
  std::optional<std::string> string(const std::string& key);
  // An array of exactly three numbers.
  std::optional<engine::Vec3> vec3(const std::string& key);
  // A sub-table, itself strict.
  std::optional<TomlTable> table(const std::string& key);
  // An array of tables.
  std::vector<TomlTable> tables(const std::string& key);
  // Raw node (already marked as read), for arrays of custom shape.
  const toml::node* node(const std::string& key);

  // Assign-if-present helpers for definition structs.
  void read(const std::string& key, double& out);
  void read(const std::string& key, int& out);
  void read(const std::string& key, bool& out);
  void read(const std::string& key, std::string& out);
  void read(const std::string& key, engine::Vec3& out);

  // Throws for the first key that nothing read.
  void finish() const;

  // "file:line: what" at the given node (or at the table when null).
  [[noreturn]] void fail(const toml::node* at, const std::string& what) const;
  const std::string& file() const { return file_; }

 private:
  const toml::node* take(const std::string& key);
  std::string qualified(const std::string& key) const;

  const toml::table* table_;
  std::string file_;
  std::string where_;
  std::unordered_set<std::string> used_;
};

}  // namespace mtcut::app
