#!/usr/bin/env bash
# docs/dds/security/make-test-pki.sh — a test PKI and DDS Security documents for onetip's DDS link, made
# with the openssl command line only (docs/dds/README.md, "Security").
#
#   bash docs/dds/security/make-test-pki.sh OUT_DIR [NAME ...]     (default names: sensor operator)
#
# writes into OUT_DIR (created; existing files of the same names are replaced):
#   ca_cert.pem, ca_key.pem      one self-signed CA (EC P-256, 10 years): it certifies the identities
#                                and signs the governance and permissions documents
#   NAME_cert.pem, NAME_key.pem  one identity per NAME, subject "/O=onetip/CN=NAME", signed by the CA
#   governance.xml/.p7s          domains 0-230 (the most Cyclone's access control takes): no unauthenticated participant, join access control,
#                                discovery, liveliness and every topic's data and metadata encrypted
#   permissions.xml/.p7s         one grant per NAME: publish and subscribe to every topic on domains
#                                0-232, valid 10 years from today
#   NAME.xml                     the Cyclone DDS <Security> section for NAME: the three plugins of
#                                Debian's libddsc0debian (absolute paths) and the files above; run as
#                                NAME with  CYCLONEDDS_URI=file://OUT_DIR/NAME.xml onetip ...
# The CA's key lies beside its certificate: this is a PKI for tests and a first set-up. For a
# deployment keep ca_key.pem offline and give each machine its own NAME_key.pem only.
# ONETIP_DDS_SECURITY_PLUGINS=DIR names the folder of libdds_security_{auth,ac,crypto}.so when it is
# not Debian's. Exits 1 naming what is missing (openssl, the plugins) or the openssl step that failed.
set -euo pipefail

usage="usage: make-test-pki.sh OUT_DIR [NAME ...]"
[ $# -ge 1 ] || { echo "make-test-pki: $usage" >&2; exit 2; }
out=$1
shift
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(sensor operator)
for n in "${names[@]}"; do
  [[ "$n" =~ ^[A-Za-z0-9_-]+$ ]] || { echo "make-test-pki: name '$n': use letters, digits, '_' and '-' only" >&2; exit 2; }
done
command -v openssl >/dev/null || { echo "make-test-pki: the openssl program is missing (Debian: openssl)" >&2; exit 1; }

plugins=${ONETIP_DDS_SECURITY_PLUGINS:-}
if [ -z "$plugins" ]; then
  for d in /usr/lib/*/libddsc0debian /usr/lib/libddsc0debian /usr/local/lib /usr/lib; do
    [ -f "$d/libdds_security_auth.so" ] && { plugins=$d; break; }
  done
fi
for p in auth ac crypto; do
  [ -f "$plugins/libdds_security_$p.so" ] || {
    echo "make-test-pki: libdds_security_$p.so not found${plugins:+ in $plugins} (Debian: libddsc0debian;" \
      "or set ONETIP_DDS_SECURITY_PLUGINS)" >&2
    exit 1
  }
done

mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
step() {  # runs one openssl step quietly; on failure prints its output and names it
  local what=$1 log
  shift
  if ! log=$("$@" 2>&1); then
    echo "make-test-pki: $what failed: $log" >&2
    exit 1
  fi
}
key() { step "key $1" openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:prime256v1 -out "$1"; }

key ca_key.pem
step "CA certificate" openssl req -x509 -new -key ca_key.pem -out ca_cert.pem -days 3650 -subj "/O=onetip/CN=onetip test CA"
for n in "${names[@]}"; do
  key "${n}_key.pem"
  step "$n request" openssl req -new -key "${n}_key.pem" -out "${n}.csr" -subj "/O=onetip/CN=$n"
  step "$n certificate" openssl x509 -req -in "${n}.csr" -CA ca_cert.pem -CAkey ca_key.pem -CAcreateserial \
    -out "${n}_cert.pem" -days 3650
  rm -f "${n}.csr"
done

domains="<domains><id_range><min>0</min><max>230</max></id_range></domains>"
cat >governance.xml <<XML
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      $domains
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>NONE</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
XML

now=$(date -u +%Y-%m-%dT%H:%M:%S)
until=$(date -u -d "+10 years" +%Y-%m-%dT%H:%M:%S)
{
  echo '<?xml version="1.0" encoding="UTF-8"?>'
  echo '<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"'
  echo '     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">'
  echo '  <permissions>'
  for n in "${names[@]}"; do
    cat <<XML
    <grant name="$n">
      <subject_name>O=onetip,CN=$n</subject_name>
      <validity><not_before>$now</not_before><not_after>$until</not_after></validity>
      <allow_rule>
        $domains
        <publish><topics><topic>*</topic></topics></publish>
        <subscribe><topics><topic>*</topic></topics></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
XML
  done
  echo '  </permissions>'
  echo '</dds>'
} >permissions.xml

for doc in governance permissions; do
  step "signing $doc.xml" openssl smime -sign -text -in "$doc.xml" -out "$doc.p7s" -signer ca_cert.pem -inkey ca_key.pem
done

for n in "${names[@]}"; do
  cat >"$n.xml" <<XML
<CycloneDDS><Domain Id="any"><Security>
  <Authentication>
    <Library path="$plugins/libdds_security_auth.so" initFunction="init_authentication" finalizeFunction="finalize_authentication"/>
    <IdentityCA>file:$out/ca_cert.pem</IdentityCA>
    <IdentityCertificate>file:$out/${n}_cert.pem</IdentityCertificate>
    <PrivateKey>file:$out/${n}_key.pem</PrivateKey>
  </Authentication>
  <AccessControl>
    <Library path="$plugins/libdds_security_ac.so" initFunction="init_access_control" finalizeFunction="finalize_access_control"/>
    <PermissionsCA>file:$out/ca_cert.pem</PermissionsCA>
    <Governance>file:$out/governance.p7s</Governance>
    <Permissions>file:$out/permissions.p7s</Permissions>
  </AccessControl>
  <Cryptographic>
    <Library path="$plugins/libdds_security_crypto.so" initFunction="init_crypto" finalizeFunction="finalize_crypto"/>
  </Cryptographic>
</Security></Domain></CycloneDDS>
XML
done
echo "make-test-pki: ${names[*]} in $out (CYCLONEDDS_URI=file://$out/NAME.xml)"
