#include "flowform/mesh/GeoScript.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "flowform/core/Files.hpp"
#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

namespace fs = std::filesystem;

/// A token of the .geo language, as far as the rule needs: identifiers, string literals and
/// single punctuation characters, each with its line.
struct Token {
  enum class Kind { Identifier, String, Punct } kind;
  std::string text;  ///< the identifier, the string's contents, or the character
  int line;
};

/// Splits the script into tokens, skipping // and /* */ comments and white space.
std::vector<Token> tokenize(const std::string& text, const std::string& path) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      const int start = line;
      i += 2;
      while (i + 1 < n && !(text[i] == '*' && text[i + 1] == '/')) line += text[i++] == '\n';
      if (i + 1 >= n)
        throw InputError("mesh file '" + path + "', line " + std::to_string(start) + ": a /* comment is not closed");
      i += 2;
    } else if (c == '"') {
      const int start = line;
      std::string s;
      ++i;
      while (i < n && text[i] != '"') {
        if (text[i] == '\\' && i + 1 < n) ++i;
        line += text[i] == '\n';
        s += text[i++];
      }
      if (i >= n)
        throw InputError("mesh file '" + path + "', line " + std::to_string(start) + ": a string is not closed");
      ++i;
      tokens.push_back({Token::Kind::String, s, start});
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < n && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
      tokens.push_back({Token::Kind::Identifier, text.substr(i, j - i), line});
      i = j;
    } else {
      tokens.push_back({Token::Kind::Punct, std::string(1, c), line});
      ++i;
    }
  }
  return tokens;
}

const std::set<std::string> kRefusedCommands = {
    "SystemCall", "NonBlockingSystemCall", "System", "OnelabRun", "Save",      "Print",
    "Plugin",     "CreateDir",             "DeleteFile", "RenameFile", "Exit"};
const std::set<std::string> kRefusedOptionCategories = {"General", "Print", "Solver"};
const std::set<std::string> kFileReaders = {"Include", "Merge", "MergeWithBoundingBox", "ShapeFromFile"};

bool isPunct(const std::vector<Token>& t, std::size_t k, char c) {
  return k < t.size() && t[k].kind == Token::Kind::Punct && t[k].text[0] == c;
}

/// `file` (as written after a file-reading command) resolved against `dir`, if it lies inside it.
bool insideFolder(const fs::path& dir, const std::string& file, fs::path& resolved) {
  const fs::path p(file);
  resolved = (p.is_absolute() ? p : dir / p).lexically_normal();
  const fs::path rel = resolved.lexically_relative(dir.lexically_normal());
  return !rel.empty() && *rel.begin() != "..";
}

void checkFile(const fs::path& path, std::vector<fs::path>& visiting) {
  const std::string where = path.string();
  std::string text;
  if (!readWholeFile(where, text)) throw InputError("mesh file '" + where + "' cannot be read");
  const std::vector<Token> t = tokenize(text, where);
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  auto refuse = [&](int line, const std::string& what) {
    throw InputError("mesh file '" + where + "', line " + std::to_string(line) + ": " + what +
                     " — flowform refuses .geo commands that reach outside the meshing (shell "
                     "commands, programs, file writes, files outside the .geo's folder; README "
                     "\"What a .geo may do\")");
  };
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k].kind != Token::Kind::Identifier) continue;
    if (k > 0 && isPunct(t, k - 1, '.')) continue;  // a member name, as in Mesh.SaveAll
    const std::string& word = t[k].text;
    if (kRefusedOptionCategories.count(word) && isPunct(t, k + 1, '.'))
      refuse(t[k].line, "the option " + word + "." + (k + 2 < t.size() ? t[k + 2].text : std::string()) +
                            " (the " + word + " options name files and programs)");
    if (kRefusedCommands.count(word)) refuse(t[k].line, "the command " + word);
    if (word == "Printf" || word == "Sprintf") {
      // Printf ( ... ) > "file" : a redirection follows the closing parenthesis.
      std::size_t j = k + 1;
      if (!isPunct(t, j, '(')) continue;
      int depth = 0;
      for (; j < t.size(); ++j) {
        if (isPunct(t, j, '(')) ++depth;
        if (isPunct(t, j, ')') && --depth == 0) break;
      }
      if (isPunct(t, j + 1, '>')) refuse(t[k].line, word + " with an output redirection (a file write)");
    }
    if (kFileReaders.count(word)) {
      if (k + 1 >= t.size() || t[k + 1].kind != Token::Kind::String || !isPunct(t, k + 2, ';'))
        refuse(t[k].line, word + " with a computed file name (a string literal is required)");
      fs::path resolved;
      if (!insideFolder(dir, t[k + 1].text, resolved))
        refuse(t[k].line, word + " \"" + t[k + 1].text + "\", which lies outside the folder '" + dir.string() + "'");
      if (word == "Include") {
        if (std::find(visiting.begin(), visiting.end(), resolved) != visiting.end())
          throw InputError("mesh file '" + where + "', line " + std::to_string(t[k].line) + ": Include \"" +
                           t[k + 1].text + "\" includes itself (a cycle)");
        if (!fs::is_regular_file(resolved))
          throw InputError("mesh file '" + where + "', line " + std::to_string(t[k].line) + ": Include \"" +
                           t[k + 1].text + "\": no such file");
        visiting.push_back(resolved);
        checkFile(resolved, visiting);
        visiting.pop_back();
      }
    }
  }
}

}  // namespace

void checkGeoScript(const std::string& path) {
  std::vector<fs::path> visiting{fs::path(path).lexically_normal()};
  checkFile(visiting.front(), visiting);
}

}  // namespace flowform
