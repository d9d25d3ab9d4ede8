SystemCall "touch /tmp/x";
Merge "other.geo";
