// Decodes LCM log files with the message classes of a jar, matching each event's fingerprint to
// a class the way lcm-spy does. One line per event:
//   file <TAB> utime <TAB> channel <TAB> class <TAB> field=value;...   ("-" and no fields when unknown)
// usage: java -cp lcm.jar:TYPES.jar:<this class> LcmLogDecode TYPES.jar LOG...

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.Enumeration;
import java.util.HashMap;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

import lcm.logging.Log;

public class LcmLogDecode {
  public static void main(String[] args) throws Exception {
    if (args.length < 2) {
      System.err.println("usage: LcmLogDecode TYPES.jar LOG...");
      System.exit(2);
    }
    Map<Long, Class<?>> types = typesByFingerprint(args[0]);
    for (int i = 1; i < args.length; ++i) decode(args[i], types);
  }

  static Map<Long, Class<?>> typesByFingerprint(String jarPath) throws Exception {
    Map<Long, Class<?>> types = new HashMap<>();
    try (JarFile jar = new JarFile(jarPath)) {
      for (Enumeration<JarEntry> entries = jar.entries(); entries.hasMoreElements();) {
        String name = entries.nextElement().getName();
        if (!name.endsWith(".class") || name.contains("$")) continue;
        Class<?> type = Class.forName(name.substring(0, name.length() - 6).replace('/', '.'));
        try {
          types.put(type.getField("LCM_FINGERPRINT").getLong(null), type);
        } catch (NoSuchFieldException notAMessage) {
          // a helper class in the jar
        }
      }
    }
    return types;
  }

  static void decode(String path, Map<Long, Class<?>> types) throws Exception {
    Log log = new Log(path, "r");
    try {
      while (true) {
        Log.Event event;
        try {
          event = log.readNext();
        } catch (EOFException end) {
          break;
        }
        long fingerprint = event.data.length >= 8
            ? new DataInputStream(new ByteArrayInputStream(event.data)).readLong() : 0;
        Class<?> type = types.get(fingerprint);
        String prefix = path + "\t" + event.utime + "\t" + event.channel + "\t";
        if (type == null) {
          System.out.println(prefix + "-\t");
          continue;
        }
        Object message = type.getConstructor(byte[].class).newInstance((Object) event.data);
        System.out.println(prefix + type.getName() + "\t" + fields(message));
      }
    } finally {
      log.close();
    }
  }

  static String fields(Object message) throws IllegalAccessException {
    StringBuilder text = new StringBuilder();
    for (Field field : message.getClass().getFields()) {
      if (Modifier.isStatic(field.getModifiers())) continue;
      text.append(field.getName()).append('=').append(value(field.get(message))).append(';');
    }
    return text.toString();
  }

  static String value(Object v) {
    if (v == null || !v.getClass().isArray()) return String.valueOf(v);
    StringBuilder text = new StringBuilder("[");
    for (int i = 0; i < Array.getLength(v); ++i) {
      if (i > 0) text.append(", ");
      text.append(value(Array.get(v, i)));
    }
    return text.append(']').toString();
  }
}
