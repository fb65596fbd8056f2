#!/bin/sh
# same_samples.sh - ctest same_samples: the double HG and Rayleigh samples
# bit for bit the same in every build.  Runs each test_accuracy binary given
# (the default build, MIST_NO_LONG_DOUBLE with Dekker's product, and with
# fma) with MIST_FINGERPRINT=1, which prints a hash of 4e5 samples' bits
# (tests/test_accuracy.c: fingerprint), and fails unless all agree.  Its
# control: the first binary with MIST_FINGERPRINT=2 (one sample's lowest
# bit flipped) must differ.
ref=$(MIST_FINGERPRINT=1 "$1") || { echo "same_samples: $1 failed"; exit 1; }
if [ "$ref" = "fast-math" ]; then     # (test_accuracy.c says why)
    echo "same_samples: built with -ffast-math: skipped"
    exit 77
fi
echo "same_samples: $ref  $1"
ctl=$(MIST_FINGERPRINT=2 "$1") || { echo "same_samples: $1 failed"; exit 1; }
if [ -z "$ref" ] || [ "$ctl" = "$ref" ]; then
    echo "same_samples: FAIL: the control (one bit flipped) gives the same fingerprint"
    exit 1
fi
bad=0
for b in "$@"; do
    f=$(MIST_FINGERPRINT=1 "$b") || { echo "same_samples: $b failed"; exit 1; }
    echo "same_samples: $f  $b"
    [ "$f" = "$ref" ] || bad=1
done
[ $bad = 0 ] || { echo "same_samples: FAIL: the builds' samples differ"; exit 1; }
echo "same_samples: $# builds, the same samples; control differs ($ctl)"
