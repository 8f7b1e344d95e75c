#include "front_end.h"

#include <cstdio>
#include <iostream>
#include <new>

#include "core/error.h"
#include "core/memory_limit.h"

namespace aliaslab {

std::string FrontEnd::flag(const std::string& key) const {
  const auto it = flags.find(key);
  return it == flags.end() ? key : it->second;
}

std::string FrontEnd::message(const std::exception& e) const {
  const auto* option = dynamic_cast<const OptionError*>(&e);
  std::string text = option ? flag(option->key()) + ": " + option->message() : std::string(e.what());
  for (const auto& [key, name] : flags)
    for (size_t at = 0; (at = text.find("{" + key + "}", at)) != std::string::npos; at += name.size())
      text.replace(at, key.size() + 2, name);
  return text;
}

int runFrontEnd(const FrontEnd& p, const std::function<int()>& body) {
  try {
    return body();
  } catch (const OptionError& e) {
    std::cerr << p.program << ": " << p.message(e) << "\n";
    return p.optionExit;
  } catch (const InputError& e) {
    std::cerr << p.program << ": " << p.message(e) << "\n";
    return p.inputExit;
  } catch (const std::bad_alloc&) {
    const MemoryLimit limit = memoryLimit();
    char figure[200];
    std::snprintf(figure, sizeof figure, "%.2f GB, %s", limit.bytes / 1e9, limit.source.c_str());
    std::cerr << p.program << ": out of memory: the run needed more than this process may use (" << figure
              << "); give a smaller size, fewer samples per pixel or fewer threads\n";
    return p.failureExit;
  } catch (const std::exception& e) {
    std::cerr << p.program << ": " << p.failurePrefix << p.message(e) << "\n";
    return p.failureExit;
  }
}

}  // namespace aliaslab
