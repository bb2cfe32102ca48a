# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Sourced by scripts/test.sh and scripts/fuzz.sh: how sanitized processes run. Testing/CMakeLists.txt gives the
# tests the same options (VR_SANITIZER_ENVIRONMENT), so that a plain ctest in a sanitizer build uses them too.
_vr_sanitizers_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# detect_leaks: LeakSanitizer at exit; check_initialization_order and detect_stack_use_after_return: more bugs found;
# abort_on_error=0 and exitcode 1 (the defaults) let a test see a failing exit status.
export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=${_vr_sanitizers_dir}/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
unset _vr_sanitizers_dir
