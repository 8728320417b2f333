#!/usr/bin/env bash
# The tf tutorials' static transforms, with the seed's commands in ROS 1's argument forms:
#   x y z yaw pitch roll frame_id child_frame_id period_ms     (base_link -> laser_link)
#   x y z qx qy qz qw frame_id child_frame_id period_ms        (base_link -> camera_link)
# and map -> odom, as a robot without localization publishes it.
# Run: bash examples/static_transforms.sh [--duration S]       (Ctrl-C stops all three)
#      robotmodel tf2_echo base_link laser_link                 (in another terminal)
set -euo pipefail
read -r -a rm <<< "${ROBOTMODEL:-robotmodel}"
duration=""
if [ "${1:-}" = "--duration" ]; then duration="${2:?--duration needs seconds}"; fi

"${rm[@]}" static_transform_publisher 0.15 0 0.3 0 0 0 base_link laser_link 100 &
"${rm[@]}" static_transform_publisher 0.1 0 0.2 0 0 0 1 base_link camera_link 100 &
"${rm[@]}" static_transform_publisher 0 0 0 0 0 0 map odom 100 &
trap 'kill $(jobs -p) 2>/dev/null; wait' EXIT
trap 'exit 0' INT TERM
# `wait` (unlike a foreground sleep) returns at once when a signal arrives.
if [ -n "$duration" ]; then sleep "$duration" & wait $!; else wait; fi
