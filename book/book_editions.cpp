#include "book_editions.h"

namespace booktool {

Edition editionNamed(const std::string& s) {
  if (s == "student") return Edition::Student;
  if (s == "teacher") return Edition::Teacher;
  throw std::runtime_error("unknown edition '" + s + "' (student or teacher)");
}

bool solutionMarker(const std::string& line, const std::string& word, bool md,
                    std::string& id, bool& remove) {
  std::size_t a = line.find_first_not_of(" \t");
  if (a == std::string::npos) return false;
  const std::string lead = (md ? "<!-- " : "// ") + word + " SOLUTION ";
  if (line.compare(a, lead.size(), lead) != 0) return false;
  std::string rest = line.substr(a + lead.size());
  while (!rest.empty() && (rest.back() == '\r' || rest.back() == ' ')) rest.pop_back();
  if (md) {
    if (rest.size() < 3 || rest.compare(rest.size() - 3, 3, "-->") != 0) return false;
    rest.erase(rest.size() - 3);
    while (!rest.empty() && rest.back() == ' ') rest.pop_back();
  }
  const std::size_t sp = rest.find(' ');
  id = rest.substr(0, sp);
  remove = sp != std::string::npos && rest.find("(remove)", sp) != std::string::npos;
  return !id.empty();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string s;
  while (std::getline(in, s)) out.push_back(s);
  return out;
}

std::vector<SolutionBlock> solutionBlocks(const std::string& text, const std::string& file,
                                          bool md) {
  std::vector<SolutionBlock> out;
  const std::vector<std::string> lines = splitLines(text);
  SolutionBlock* open = nullptr;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::string id;
    bool rm = false;
    const std::string where = file + ":" + std::to_string(k + 1) + ": ";
    if (solutionMarker(lines[k], "BEGIN", md, id, rm)) {
      if (open) throw std::runtime_error(where + "BEGIN SOLUTION " + id + " inside the block of " + open->id);
      out.push_back({id, file, int(k + 1), md, {}});
      open = &out.back();
    } else if (solutionMarker(lines[k], "END", md, id, rm)) {
      if (!open || open->id != id) throw std::runtime_error(where + "END SOLUTION " + id + " without its BEGIN");
      open = nullptr;
    } else if (open) {
      open->lines.push_back(lines[k]);
    }
  }
  if (open) throw std::runtime_error(file + ":" + std::to_string(open->line) + ": BEGIN SOLUTION " +
                                     open->id + " is never closed");
  return out;
}

std::string editionCode(const std::string& text, const std::string& file, Edition ed) {
  solutionBlocks(text, file, false);  // balanced, or an error
  std::string out;
  bool inside = false;
  for (const std::string& line : splitLines(text)) {
    std::string id;
    bool rm = false;
    const std::string indent = line.substr(0, line.find_first_not_of(" \t"));
    if (solutionMarker(line, "BEGIN", false, id, rm)) {
      inside = true;
      if (ed == Edition::Teacher)
        out += indent + "// Answer to exercise " + id + " (teacher's edition) from here" + (rm ? ": a helper" : "") + "\n";
      else if (!rm)
        out += indent + "throw std::logic_error(\"exercise " + id + ": not implemented yet\");\n";
      continue;
    }
    if (solutionMarker(line, "END", false, id, rm)) {
      inside = false;
      if (ed == Edition::Teacher) out += indent + "// End of the answer to exercise " + id + "\n";
      continue;
    }
    if (!inside || ed == Edition::Teacher) out += line + "\n";
  }
  return out;
}

std::string editionPage(const std::string& text, const std::string& file, Edition ed) {
  solutionBlocks(text, file, true);
  std::string out;
  bool inside = false;
  for (const std::string& line : splitLines(text)) {
    std::string id;
    bool rm = false;
    const std::string studentLead = "<!-- student:";
    const std::size_t lead = line.find_first_not_of(" \t");
    if (lead != std::string::npos && line.compare(lead, studentLead.size(), studentLead) == 0) {
      const std::size_t close = line.rfind("-->");
      if (inside || close == std::string::npos || close < lead + studentLead.size())
        throw std::runtime_error(file + ": a '<!-- student: ... -->' line inside a solution block or not closed on its line");
      if (ed == Edition::Student) {
        std::string t = line.substr(lead + studentLead.size(), close - lead - studentLead.size());
        t.erase(0, t.find_first_not_of(' '));
        t.erase(t.find_last_not_of(' ') + 1);
        out += t + "\n";
      }
      continue;
    }
    if (solutionMarker(line, "BEGIN", true, id, rm)) {
      inside = true;
      if (ed == Edition::Teacher)
        out += "\\htmlonly[block]<div class=\"answer\"><div class=\"answerhead\">Answer to exercise " + id +
               " (teacher's edition only)</div>\\endhtmlonly\n";
      else
        out += "\n";  // keeps the paragraphs around the block apart
      continue;
    }
    if (solutionMarker(line, "END", true, id, rm)) {
      inside = false;
      if (ed == Edition::Teacher) out += "\\htmlonly[block]</div>\\endhtmlonly\n";
      continue;
    }
    if (inside && (line.find("<!-- values:") != std::string::npos || line.find("<!-- phrases:") != std::string::npos)) continue;
    if (!inside || ed == Edition::Teacher) out += line + "\n";
  }
  return out;
}

std::string studentLinks(const std::string& page) {
  std::string out = page;
  const std::string ref = "\\ref solutions \"";
  std::size_t at = 0;
  while ((at = out.find(ref, at)) != std::string::npos) {
    const std::size_t close = out.find('"', at + ref.size());
    if (close == std::string::npos) break;
    const std::string label = out.substr(at + ref.size(), close - at - ref.size());
    out.replace(at, close + 1 - at, label + " (teacher's edition)");
    at += label.size();
  }
  return out;
}

std::vector<std::string> blockValues(const SolutionBlock& b, const std::string& what) {
  std::vector<std::string> out;
  const std::string lead = "<!-- " + what + ":";
  for (const std::string& l : b.lines) {
    const std::size_t at = l.find(lead);
    if (at == std::string::npos) continue;
    std::string v = l.substr(at + lead.size(), l.find("-->", at) - at - lead.size());
    std::size_t s = 0;
    while (s <= v.size()) {
      std::size_t bar = v.find('|', s);
      if (bar == std::string::npos) bar = v.size();
      std::string item = v.substr(s, bar - s);
      item.erase(0, item.find_first_not_of(" \t"));
      item.erase(item.find_last_not_of(" \t") + 1);
      if (!item.empty()) out.push_back(item);
      s = bar + 1;
    }
  }
  return out;
}

std::string squeeze(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::vector<std::string> snippetLines(const std::string& text, const std::string& name) {
  std::vector<std::string> out;
  bool inside = false;
  const std::string mark = "//! [" + name + "]";
  for (const std::string& l : splitLines(text)) {
    if (l.find(mark) != std::string::npos) {
      if (inside) return out;
      inside = true;
      continue;
    }
    if (inside) out.push_back(l);
  }
  return {};
}

}  // namespace booktool
