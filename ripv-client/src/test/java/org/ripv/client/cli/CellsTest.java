package org.ripv.client.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.json.Json;

class CellsTest {
    @Test
    void numbersBecomeNumbersNullStaysNullTextStaysText() {
        List<Object> row = Cells.row(List.of("INTEGER", "BIGINT", "DOUBLE", "DECIMAL", "VARCHAR", "INTEGER", "BOOLEAN", "bool", "float8", "numeric(10,2)"),
                new String[] {"42", "123456789012345678901", "2.5", "10.10", "007", null, "true", "f", "NaN", "-1.5"});
        assertThat(Json.write(row)).isEqualTo("[42,123456789012345678901,2.5,10.10,\"007\",null,true,false,\"NaN\",-1.5]");
    }

    @Test
    void aCellThatIsNotANumberStaysText() {
        assertThat(Cells.value("INTEGER", "n/a")).isEqualTo("n/a");
    }
}
