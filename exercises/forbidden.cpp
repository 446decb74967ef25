// The forbidden check of scripts/exercise.sh grade: `forbidden ID FILE [WORD...]` reads the
// solution regions of exercise ID in FILE as the compiler does (comments, string and character
// literals, raw strings and digraphs understood) and prints the first forbidden use as
// "FILE:LINE: WHAT", exit status 1; nothing and status 0 when the regions are clean.
// A WORD is a name (std::map: the tokens std, ::, map) or an operator (?, &&) and matches whole
// tokens, never text inside a literal or a comment. Always refused: the preprocessor and line
// splices, braces that close the enclosing function, extern, asm, names the implementation
// reserves (__x, _X, so _Z... mangled names too), and calls that leave the process's own
// computation (system, popen, fork, exec*, ...). `forbidden --shape ID FILE` prints the
// regions' tokens with names and literals blurred instead, for exercise.sh similar.
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Token {
  std::string text;
  int line;
  bool name;
};

// The marker rule of exercise.sh: "<WORD> SOLUTION <id>" followed by the end of the line or a space.
bool marks(const std::string& line, const std::string& word, const std::string& id) {
  const std::string t = word + " SOLUTION " + id;
  const auto k = line.find(t);
  if (k == std::string::npos) return false;
  const auto after = k + t.size();
  return after == line.size() || line[after] == ' ';
}

[[noreturn]] void refuse(const std::string& file, int line, const std::string& what) {
  std::printf("%s:%d: %s\n", file.c_str(), line, what.c_str());
  std::exit(1);
}

// The tokens of one region; `first` is the file line of its first line.
std::vector<Token> tokenize(const std::string& src, int first, const std::string& file) {
  std::vector<Token> out;
  std::size_t i = 0;
  int line = first;
  const auto at = [&](std::size_t k) { return k < src.size() ? src[k] : '\0'; };
  while (i < src.size()) {
    const char c = src[i];
    if (c == '\\' && (at(i + 1) == '\n' || (at(i + 1) == '\r' && at(i + 2) == '\n')))
      refuse(file, line, "a line splice (backslash at the end of a line)");
    if (c == '\n') { ++line; ++i; continue; }
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    if (c == '/' && at(i + 1) == '/') {
      while (i < src.size() && src[i] != '\n') {
        if (src[i] == '\\' && (at(i + 1) == '\n' || at(i + 1) == '\r')) refuse(file, line, "a line splice in a comment");
        ++i;
      }
      continue;
    }
    if (c == '/' && at(i + 1) == '*') {
      const auto e = src.find("*/", i + 2);
      if (e == std::string::npos) refuse(file, line, "a comment that the region does not close");
      for (std::size_t k = i; k < e; ++k) line += src[k] == '\n';
      i = e + 2;
      continue;
    }
    // A name, or the prefix of a literal (u8"", L'', R"d(...)d").
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < src.size() && (std::isalnum(static_cast<unsigned char>(src[j])) || src[j] == '_')) ++j;
      const std::string word = src.substr(i, j - i);
      const bool prefix = word == "R" || word == "u8R" || word == "uR" || word == "UR" || word == "LR";
      if (prefix && at(j) == '"') {
        const auto open = src.find('(', j + 1);
        if (open == std::string::npos) refuse(file, line, "a raw string without '('");
        const std::string close = ")" + src.substr(j + 1, open - j - 1) + "\"";
        const auto e = src.find(close, open + 1);
        if (e == std::string::npos) refuse(file, line, "a raw string that the region does not close");
        for (std::size_t k = i; k < e; ++k) line += src[k] == '\n';
        out.push_back({"\"\"", line, false});
        i = e + close.size();
        continue;
      }
      if ((word == "u8" || word == "u" || word == "U" || word == "L") && (at(j) == '"' || at(j) == '\'')) {
        i = j;  // the literal follows
        continue;
      }
      out.push_back({word, line, true});
      i = j;
      continue;
    }
    if (c == '"' || c == '\'') {
      std::size_t j = i + 1;
      while (j < src.size() && src[j] != c) {
        if (src[j] == '\n') refuse(file, line, "a literal that the line does not close");
        j += src[j] == '\\' ? 2 : 1;
      }
      if (j >= src.size()) refuse(file, line, "a literal that the region does not close");
      out.push_back({c == '"' ? "\"\"" : "''", line, false});
      i = j + 1;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(at(i + 1))))) {
      std::size_t j = i + 1;  // a pp-number: digits, letters, '.', digit separators, signed exponents
      while (j < src.size()) {
        const char d = src[j];
        if (std::isalnum(static_cast<unsigned char>(d)) || d == '.' || d == '_' ||
            (d == '\'' && std::isalnum(static_cast<unsigned char>(at(j + 1)))))
          ++j;
        else if ((d == '+' || d == '-') && std::string("eEpP").find(src[j - 1]) != std::string::npos)
          ++j;
        else
          break;
      }
      out.push_back({"0", line, false});
      i = j;
      continue;
    }
    // Punctuators, longest first; digraphs as what they stand for.
    static const std::vector<std::pair<std::string, std::string>> puncts = {
        {"%:%:", "##"}, {"<=>", "<=>"}, {"...", "..."}, {"<<=", "<<="}, {">>=", ">>="}, {"->*", "->*"},
        {"<%", "{"}, {"%>", "}"}, {"<:", "["}, {":>", "]"}, {"%:", "#"}, {"::", "::"}, {"&&", "&&"},
        {"||", "||"}, {"##", "##"}, {"->", "->"}, {"++", "++"}, {"--", "--"}, {"<<", "<<"}, {">>", ">>"},
        {"<=", "<="}, {">=", ">="}, {"==", "=="}, {"!=", "!="}, {"+=", "+="}, {"-=", "-="}, {"*=", "*="},
        {"/=", "/="}, {"%=", "%="}, {"&=", "&="}, {"|=", "|="}, {"^=", "^="}, {".*", ".*"}};
    bool matched = false;
    for (const auto& p : puncts)
      if (src.compare(i, p.first.size(), p.first) == 0) {
        // "<::" is "<" then "::" unless followed by ':' or '>' (the digraph exception).
        if (p.first == "<:" && at(i + 2) == ':' && at(i + 3) != ':' && at(i + 3) != '>') break;
        out.push_back({p.second, line, false});
        i += p.first.size();
        matched = true;
        break;
      }
    if (matched) continue;
    out.push_back({std::string(1, c), line, false});
    ++i;
  }
  return out;
}

void check(const std::vector<Token>& t, const std::vector<std::string>& words, const std::string& file) {
  static const std::set<std::string> always = {
      "extern", "asm", "system", "popen", "fork", "vfork", "clone", "syscall", "posix_spawn", "posix_spawnp",
      "dlopen", "dlsym", "execl", "execle", "execlp", "execv", "execve", "execvp", "execvpe", "fexecve",
      "kill", "ptrace", "signal", "sigaction", "atexit", "at_quick_exit", "set_terminate"};
  int depth = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const Token& x = t[k];
    if (x.text == "#" || x.text == "##") refuse(file, x.line, "the preprocessor ('#')");
    if (x.text == "{") ++depth;
    if (x.text == "}" && --depth < 0) refuse(file, x.line, "a '}' that closes the function around the region");
    if (x.name) {
      if (always.count(x.text)) refuse(file, x.line, "'" + x.text + "'");
      if (x.text.rfind("exec", 0) == 0 && x.text.size() <= 8) refuse(file, x.line, "'" + x.text + "'");
      if (x.text.rfind("__", 0) == 0 || (x.text.size() > 1 && x.text[0] == '_' && std::isupper(static_cast<unsigned char>(x.text[1]))))
        refuse(file, x.line, "'" + x.text + "' (a name reserved for the implementation)");
    }
    for (const std::string& w : words) {
      // The word's own tokens (a name, "::", an operator), matched in sequence.
      const std::vector<Token> wt = tokenize(w, 0, "(the forbid list)");
      if (wt.empty() || k + wt.size() > t.size()) continue;
      bool same = true;
      for (std::size_t m = 0; m < wt.size() && same; ++m) same = t[k + m].text == wt[m].text;
      if (same) refuse(file, x.line, "'" + w + "'");
    }
  }
  if (depth != 0) refuse(file, t.empty() ? 0 : t.back().line, "a '{' that the region does not close");
}

}  // namespace

// The tokens of a region for the similarity hint of exercise.sh similar: names become "N"
// (a renamed variable changes nothing), keywords stay, literals are "L".
void printShape(const std::vector<Token>& t) {
  static const std::set<std::string> keywords = {
      "auto", "bool", "break", "case", "catch", "char", "class", "const", "continue", "default", "delete", "do",
      "double", "else", "enum", "false", "float", "for", "if", "int", "long", "new", "nullptr", "return", "short",
      "signed", "sizeof", "static", "struct", "switch", "this", "throw", "true", "try", "unsigned", "using",
      "void", "volatile", "while"};
  for (const Token& x : t)
    std::printf("%s\n", x.name ? (keywords.count(x.text) ? x.text.c_str() : "N")
                               : (x.text == "\"\"" || x.text == "''" || x.text == "0" ? "L" : x.text.c_str()));
}

int main(int argc, char** argv) {
  const bool shape = argc > 1 && std::string(argv[1]) == "--shape";
  if (shape) ++argv, --argc;
  if (argc < 3) {
    std::fprintf(stderr, "usage: forbidden [--shape] ID FILE [WORD...]\n");
    return 2;
  }
  const std::string id = argv[1], file = argv[2];
  std::ifstream in(file);
  if (!in) {
    std::fprintf(stderr, "forbidden: cannot read %s\n", file.c_str());
    return 2;
  }
  const std::vector<std::string> words(argv + 3, argv + argc);
  std::string line, body;
  int n = 0, first = 0;
  bool inside = false;
  while (std::getline(in, line)) {
    ++n;
    if (!inside && marks(line, "BEGIN", id)) {
      inside = true, body.clear(), first = n + 1;
      continue;
    }
    if (inside && marks(line, "END", id)) {
      inside = false;
      if (shape) printShape(tokenize(body, first, file));
      else check(tokenize(body, first, file), words, file);
      continue;
    }
    if (inside) body += line + "\n";
  }
  if (inside) refuse(file, first - 1, "a region without its END SOLUTION " + id + " line");
  return 0;
}
