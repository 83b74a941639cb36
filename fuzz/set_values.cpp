// --set and preset values, as every front end parses them: the first byte picks a scene, the second
// one of its parameters, the rest is the text. Besides not crashing, the schema's promises must hold:
// a refused value says why and leaves the field alone; an accepted one has canonical text that reads
// back to itself; a batch through applyValues is all-or-nothing.
#include "params/schema.h"
#include "scenes/catalogue.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include "support/require.h"

using namespace vitrine;

using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const auto scenes = sceneRegistry();
  const params::Schema& schema = scenes[data[0] % scenes.size()].schema();
  if (schema.params().empty()) return 0;
  const params::Param& param = schema.params()[data[1] % schema.params().size()];
  const std::string text(reinterpret_cast<const char*>(data + 2), size - 2);

  const auto settings = schema.makeDefaults();
  std::string error;
  if (param.parse(settings.get(), text, &error)) {
    const std::string canonical = param.format(settings.get());
    const auto again = schema.makeDefaults();
    require(param.parse(again.get(), canonical, nullptr), "canonical text is refused");
    require(param.format(again.get()) == canonical, "canonical text does not read back to itself");
  } else {
    require(!error.empty(), "a refused value gives no reason");
    require(param.format(settings.get()) == param.defaultText, "a refused value changed the field");
  }

  // The same text through applyValues (what --set does), with a second pair that must be undone when the
  // first is refused, and as a preset name.
  const auto batch = schema.makeDefaults();
  const params::Bound bound{&schema, batch.get()};
  const params::Param& other = schema.params()[(data[1] + 1u) % schema.params().size()];
  const params::KeyValues values = {{other.key, other.defaultText}, {param.key, text}};
  if (!params::applyValues(bound, values).empty())
    require(params::snapshot(bound) == params::snapshot({&schema, schema.makeDefaults().get()}),
            "a refused batch left values changed");
  params::applyPreset(bound, text);
  return 0;
}
