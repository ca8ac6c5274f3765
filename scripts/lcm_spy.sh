#!/usr/bin/env bash
# lcm-spy with cerebellum's message classes, listening on one port of the CyberDog2 interface.
# Debian's lcm-spy script passes -Xincgc, which Java 17 refuses, so this starts lcm.spy.Spy itself.
#   scripts/lcm_spy.sh [PORT] [TTL]
# PORT: 7667 motor SDK and odometry, 7669 state estimator, 7670 responses (default), 7671 commands.
# TTL: multicast ttl of the url (default 0: traffic of this machine only).
# The jar: $CEREBELLUM_LCM_JAR, else <repo>/build/lcm/cerebellum_lcmtypes.jar, else the installed one.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
port=${1:-7670}
ttl=${2:-0}
case "$port" in
  7667|7669|7670|7671) ;;
  *) echo "lcm_spy.sh: PORT must be one of 7667, 7669, 7670, 7671, got '$port'" >&2; exit 2 ;;
esac
jar=${CEREBELLUM_LCM_JAR:-}
if [[ -z "$jar" ]]; then
  for candidate in "$root/build/lcm/cerebellum_lcmtypes.jar" /usr/local/share/cerebellum/java/cerebellum_lcmtypes.jar \
                   /usr/share/cerebellum/java/cerebellum_lcmtypes.jar; do
    if [[ -f "$candidate" ]]; then jar=$candidate; break; fi
  done
fi
if [[ -z "$jar" || ! -f "$jar" ]]; then
  echo "lcm_spy.sh: no cerebellum_lcmtypes.jar (build the target cerebellum_lcm_java, or set CEREBELLUM_LCM_JAR)" >&2
  exit 1
fi
if [[ ! -f /usr/share/java/lcm.jar ]]; then
  echo "lcm_spy.sh: /usr/share/java/lcm.jar missing (Debian package: liblcm-java)" >&2
  exit 1
fi
classpath=/usr/share/java/lcm.jar:$jar
# the charts of lcm-spy need jchart2d (Debian package: libjchart2d-java); the table works without it
[[ -f /usr/share/java/jchart2d.jar ]] && classpath=$classpath:/usr/share/java/jchart2d.jar
exec java -Djava.net.preferIPv4Stack=true -Xmx128m -ea -cp "$classpath" lcm.spy.Spy \
  --lcm-url="udpm://239.255.76.67:$port?ttl=$ttl"
