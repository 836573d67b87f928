#include "platform/dri_driver.h"

#include <dlfcn.h>
#include <link.h>

#include <cstddef>
#include <string_view>

namespace rtlab {
namespace {

// RTLD_NOLOAD loads nothing new; RTLD_NODELETE pins a library that is already loaded.
int pinIfDriDriver(dl_phdr_info* info, std::size_t, void*) {
  const std::string_view name = info->dlpi_name ? info->dlpi_name : "";
  if (name.ends_with("_dri.so")) dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
  return 0;
}

} // namespace

void keepDriDriversResident() {
  dl_iterate_phdr(&pinIfDriDriver, nullptr);
}

} // namespace rtlab
