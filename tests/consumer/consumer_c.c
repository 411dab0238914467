/* C consumer of an installed onetip: only <onetip_c.h> and -lonetip, compiled
 * as C11. Checks the ABI handshake and runs the simulated sensor to its end. */
#include <onetip_c.h>
#include <stdio.h>

int main(int argc, char** argv) {
  onetip_error err;
  onetip_sensor* sensor = NULL;
  onetip_event e;
  int32_t got = 0, finished = 0, inputs = 0;
  char source[1024];
  if (argc != 2) return 2;
  snprintf(source, sizeof source, "sim:%s", argv[1]);
  if (onetip_sensor_create(ONETIP_C_ABI_VERSION, source, NULL, NULL, NULL, NULL, &sensor, &err) != ONETIP_OK ||
      onetip_sensor_start(sensor, &err) != ONETIP_OK ||
      onetip_sensor_wait_finished(sensor, 300, &finished, &err) != ONETIP_OK) {
    fprintf(stderr, "consumer_c: %s\n", err.message);
    return 1;
  }
  while (onetip_sensor_poll_event(sensor, &e, &got, &err) == ONETIP_OK && got) inputs += e.type == ONETIP_EVENT_INPUT;
  onetip_sensor_destroy(sensor, &err);
  printf("consumer_c: onetip %s, C ABI %u, %d input events\n", onetip_version_string(), onetip_abi_version(), inputs);
  return finished && inputs > 0 ? 0 : 1;
}
