#include "book_answer_scan.h"

#include "book_editions.h"

namespace booktool {

bool plainProse(const std::string& s) {
  std::string t = squeeze(s);
  if (t.rfind("- ", 0) == 0) t.erase(0, 2);  // a list item's marker is not shown as typed
  if (t.size() < 30) return false;
  for (char c : t)
    if (std::string("\\`*_{}[]<>|#@$&\"").find(c) != std::string::npos) return false;
  return true;
}

std::map<std::string, AnswerKey> answerKeys(const std::map<std::string, std::string>& code,
                                            const std::map<std::string, std::string>& pages) {
  std::map<std::string, AnswerKey> keys;
  // Spans: per file, the line numbers that belong to an answer.
  std::map<std::string, std::set<std::size_t>> span;
  std::map<std::string, std::vector<std::string>> linesOf;
  for (const auto& [f, t] : code) linesOf[f] = splitLines(t);
  std::map<std::string, std::vector<std::pair<std::string, std::size_t>>> candidates;  // id -> (file, line)
  for (const auto& [f, t] : code) {
    const auto& L = linesOf[f];
    std::string open;
    for (std::size_t k = 0; k < L.size(); ++k) {
      std::string id;
      bool rm = false;
      if (solutionMarker(L[k], "BEGIN", false, id, rm)) { open = id; span[f].insert(k); continue; }
      if (solutionMarker(L[k], "END", false, id, rm)) { open.clear(); span[f].insert(k); continue; }
      if (!open.empty()) {
        span[f].insert(k);
        candidates[open].push_back({f, k});
      }
    }
  }
  for (const auto& [pf, pt] : pages)
    for (const SolutionBlock& b : solutionBlocks(pt, pf, true)) {
      AnswerKey& key = keys[b.id];
      for (const std::string& v : blockValues(b)) key.values.insert(v);
      for (const std::string& v : blockValues(b, "phrases")) key.phrases.insert(lower(squeeze(v)));
      for (const std::string& l : b.lines) {
        if (plainProse(l)) {
          std::string t = squeeze(l);
          if (t.rfind("- ", 0) == 0) t.erase(0, 2);
          key.lines.insert(t);
        }
        // "\snippet code/x.cpp name": the quoted definition is the answer too.
        std::istringstream w(l);
        std::string cmd, file, name;
        w >> cmd >> file >> name;
        if (cmd != "\\snippet" || file.size() < 4 || file.compare(file.size() - 4, 4, ".cpp") != 0) continue;
        key.snippets.insert({file, name});
      }
    }
  // A line is distinctive if it is long and occurs nowhere outside the answers' spans.
  // "Nowhere else" also means: not part of a longer line elsewhere ("for (...)" of "for (...) {").
  std::string elsewhereText;
  for (const auto& [f, L] : linesOf)
    for (std::size_t k = 0; k < L.size(); ++k)
      if (!span[f].count(k)) elsewhereText += squeeze(L[k]) + "\n";
  struct Elsewhere {
    const std::string& text;
    std::size_t count(const std::string& line) const { return text.find(line) != std::string::npos; }
  } elsewhere{elsewhereText};
  for (const auto& [id, where] : candidates)
    for (const auto& [f, k] : where) {
      const std::string s = squeeze(linesOf[f][k]);
      std::string marker;
      bool rm = false;
      if (s.size() >= 25 && !elsewhere.count(s) && !solutionMarker(s, "BEGIN", false, marker, rm) &&
          !solutionMarker(s, "END", false, marker, rm))
        keys[id].lines.insert(s);
    }
  return keys;
}

std::vector<std::string> snippetLeaks(const std::map<std::string, AnswerKey>& keys,
                                      const std::map<std::string, std::string>& code) {
  std::vector<std::string> out;
  for (const auto& [id, k] : keys)
    for (const auto& [file, name] : k.snippets) {
      auto it = code.find(file);
      if (it == code.end()) continue;
      const auto student = snippetLines(editionCode(it->second, file, Edition::Student), name);
      const auto teacher = snippetLines(editionCode(it->second, file, Edition::Teacher), name);
      if (!teacher.empty() && student == teacher)
        out.push_back(id + ": the student edition shows the answer's snippet " + file + " [" + name +
                      "] as the teacher's does (its solution region is not marked)");
    }
  return out;
}

std::vector<std::string> editionLeaks(const std::map<std::string, AnswerKey>& keys,
                                      const std::vector<std::string>& ids,
                                      const std::string& student, const std::string& teacher) {
  std::vector<std::string> out;
  // Values are looked for with white space squeezed and none next to a sign or bracket: a
  // formula or a test name may space "4 + (6-D)/n" differently from the answer's
  // "4 + (6 - D)/n". Between two letters or digits a space stays ("16 namespace" is not 16n).
  auto bare = [](const std::string& s) {
    const std::string q = squeeze(s);
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    std::string o;
    for (std::size_t i = 0; i < q.size(); ++i)
      if (q[i] != ' ' || (i > 0 && i + 1 < q.size() && word(q[i - 1]) && word(q[i + 1]))) o += q[i];
    return o;
  };
  const std::string studentBare = bare(student), teacherBare = bare(teacher);
  const std::string studentLower = lower(student), teacherLower = lower(teacher);
  // A value is found as a whole: not inside a longer word ("16n" is not in "16namespace", the
  // line number 16 of a source listing before its code).
  auto contains = [](const std::string& text, const std::string& v) {
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = text.find(v); at != std::string::npos; at = text.find(v, at + 1)) {
      const bool before = at > 0 && word(text[at - 1]) && word(v.front());
      const bool after = at + v.size() < text.size() && word(text[at + v.size()]) && word(v.back());
      if (!before && !after) return true;
    }
    return false;
  };
  for (const std::string& id : ids) {
    auto it = keys.find(id);
    if (it == keys.end() || (it->second.lines.empty() && it->second.values.empty())) {
      out.push_back(id + ": no marked answer (no solution block with a distinctive line or value)");
      continue;
    }
    auto look = [&](const std::string& item, const std::string& needle, const std::string& s,
                    const std::string& t, const char* kind) {
      const bool value = std::string(kind) == "value";  // a line is looked for as it is
      if (value ? contains(s, needle) : s.find(needle) != std::string::npos)
        out.push_back(id + ": the student edition shows the answer's " + kind + " '" + item + "'");
      if (value ? !contains(t, needle) : t.find(needle) == std::string::npos)
        out.push_back(id + ": the teacher edition lacks the answer's " + kind + " '" + item + "'");
    };
    for (const std::string& l : it->second.lines) look(l, l, student, teacher, "line");
    for (const std::string& p : it->second.phrases) look(p, p, studentLower, teacherLower, "key phrase");
    for (const std::string& v : it->second.values) look(v, bare(v), studentBare, teacherBare, "value");
  }
  return out;
}

}  // namespace booktool
